#include "parksim/planner/motion/TimeOptimalTiming.h"

#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "parksim/planner/steering/ReedsSheppSteering.h"
#include "parksim/planner/steering/RotateTranslateRotateSteering.h"
#include "tests/support/PlanChecks.h"

namespace parksim {
namespace {

using testing::expectConsistentWithLimits;

RobotDef limitedRobot(const TimingLimits& l) {
  RobotDef r;
  r.max_wheel_speed_radps = l.max_wheel_speed_radps;
  r.max_wheel_accel_radps2 = l.max_wheel_accel_radps2;
  return r;
}

TEST(TimeOptimalTiming, StraightLineTakesThePredictedTrapezoid) {
  const RobotDef robot;
  const TimingLimits l = timingLimits(robot, 0.2);
  ASSERT_DOUBLE_EQ(l.max_wheel_speed_radps, 8.0);
  // 1 m straight: the wheels turn 1 / r = 50 rad. Periods run at one step (4 rad/s) from rest,
  // then 8 rad/s, then one step before the stop: 0.1 s * (4 + 8 (n - 2) + 4) >= 50 rad.
  const double travel = 1.0 / robot.wheel_radius_m;
  const Trajectory t = timePieces({0.1, 0.2, 0.0}, {{{1.0, 1.0}, travel}}, robot, l);
  const int n = static_cast<int>(std::ceil(travel / (0.1 * 8.0) + 1.0));
  EXPECT_NEAR(t.duration(), 0.1 * n, 1e-12);
  EXPECT_NEAR(t.points.back().pose.x, 1.1, 1e-12);
  EXPECT_NEAR(t.points.back().pose.y, 0.2, 1e-12);
  expectConsistentWithLimits(t, limitedRobot(l));
  // Continuous time: 50 / 8 + 8 / 40 = 6.45 s, less one period for whole periods.
  EXPECT_NEAR(durationLowerBound(pathPieces(t), l), 6.35, 1e-12);
  EXPECT_GE(t.duration(), durationLowerBound(pathPieces(t), l));
}

TEST(TimeOptimalTiming, RetimingKeepsTheGeometryAndMeetsTheBound) {
  const RobotDef robot;
  const TimingLimits l = timingLimits(robot, 0.2);
  const RotateTranslateRotateSteering rtr(robot);
  ReedsSheppDef rs_def;
  rs_def.turning_radius_m = 0.06;
  const ReedsSheppSteering rs(robot, rs_def);
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> pos(0.0, 1.0), ang(-kPi, kPi);
  for (int i = 0; i < 200; ++i) {
    const Pose2 from{pos(rng), pos(rng), ang(rng)};
    const Pose2 to{pos(rng), pos(rng), ang(rng)};
    const SteeringFunction& steering = i % 2 ? static_cast<const SteeringFunction&>(rtr) : rs;
    const Trajectory original = steering.steer(from, {}, to, SteerMode::kExact).trajectory;
    const Trajectory timed = retime(original, robot, l);
    expectConsistentWithLimits(timed, limitedRobot(l));
    EXPECT_EQ(timed.points.front().pose, from);
    EXPECT_NEAR(positionDistance(timed.points.back().pose, to), 0.0, 1e-9);
    EXPECT_NEAR(headingDistance(timed.points.back().pose, to), 0.0, 1e-9);
    EXPECT_NEAR(timed.pathLength(robot), original.pathLength(robot), 1e-9);
    EXPECT_EQ(timed.cusps(robot), original.cusps(robot));
    const double bound = durationLowerBound(pathPieces(original), l);
    EXPECT_GE(timed.duration(), bound - 1e-9);
    EXPECT_LE(timed.duration(), 1.6 * bound + 0.3) << i;
  }
}

TEST(TimeOptimalTiming, CuspsPassThroughHalfAStepEachWay) {
  const RobotDef robot;
  const TimingLimits l = timingLimits(robot, 0.0);
  const Trajectory t = timePieces({}, {{{1.0, 1.0}, 3.0}, {{-1.0, -1.0}, 3.0}}, robot, l);
  expectConsistentWithLimits(t, robot);
  bool crossed = false;
  for (std::size_t i = 0; i + 2 < t.points.size(); ++i) {
    const double a = t.points[i].wheels.left_radps;
    const double b = t.points[i + 1].wheels.left_radps;
    if (a > 0.0 && b < 0.0) {
      crossed = true;
      EXPECT_NEAR(a, 2.0, 1e-12);  // half of 40 rad/s^2 * 0.1 s
      EXPECT_NEAR(b, -2.0, 1e-12);
    }
  }
  EXPECT_TRUE(crossed);
  EXPECT_NEAR(t.points.back().pose.x, 0.0, 1e-12);
}

TEST(TimeOptimalTiming, ManyShortPiecesStillFitTheLimits) {
  // The study's controller changes curvature every period: pieces of one period each.
  const RobotDef robot;
  const TimingLimits l = timingLimits(robot, 0.2);
  std::vector<PathPiece> pieces;
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> c(-1.0, 1.0), len(0.001, 0.5);
  for (int i = 0; i < 300; ++i) pieces.push_back(pieceOf({c(rng), 1.0}, len(rng)));
  const Trajectory t = timePieces({}, pieces, robot, l);
  expectConsistentWithLimits(t, limitedRobot(l));
  EXPECT_GE(t.duration(), durationLowerBound(pieces, l));
}

TEST(TimeOptimalTiming, SoftStartRaisesTheAccelerationStepByStep) {
  const RobotDef robot;
  const TimingLimits hard = timingLimits(robot, 0.2, 0.02);
  const TimingLimits soft = timingLimits(robot, 0.2, 0.02, 100.0);  // J dt^2 = 0.04 rad/s
  const std::vector<PathPiece> pieces{pieceOf({1.0, 1.0}, 40.0), pieceOf({0.5, 1.0}, 5.0)};
  const Trajectory t = timePieces({}, pieces, robot, soft);
  expectConsistentWithLimits(t, limitedRobot(soft));
  // Speeds 0.04, 0.12, 0.24, ...: each period's increase one jerk step more than the last, up
  // to the acceleration step of 0.8 rad/s.
  double previous = 0.0;
  double increase = 0.0;
  for (int i = 0; i < 30; ++i) {
    const double u = t.points[i].wheels.right_radps;
    const double next = u - previous;
    EXPECT_LE(next, std::min(0.8, increase + 0.04) + 1e-9) << "period " << i;
    increase = next;
    previous = u;
  }
  EXPECT_NEAR(t.points[0].wheels.right_radps, 0.04, 1e-12);
  // Slower than the hard start by about the ramp's lag, never by more than its length.
  const double lag = t.duration() - timePieces({}, pieces, robot, hard).duration();
  EXPECT_GT(lag, 0.0);
  EXPECT_LE(lag, 0.4 + 1e-9);
  // The same geometry: timing only.
  const Pose2 a = t.points.back().pose;
  const Pose2 b = timePieces({}, pieces, robot, hard).points.back().pose;
  EXPECT_NEAR(a.x, b.x, 1e-9);
  EXPECT_NEAR(a.y, b.y, 1e-9);
  EXPECT_NEAR(timedDuration(pieces, soft), t.duration(), 1e-12);
}

}  // namespace
}  // namespace parksim
