#include "parksim/planner/tree/PathSegment.h"

#include <random>

#include <gtest/gtest.h>

#include "parksim/planner/motion/PathCost.h"
#include "parksim/planner/steering/RotateTranslateRotateSteering.h"
#include "tests/support/PlanChecks.h"

namespace parksim {
namespace {

// Straight drive from rest at `wheel` rad/s on both wheels for `periods`, then a stop.
Trajectory straight(const RobotDef& robot, const Pose2& from, double wheel, int periods) {
  Trajectory t;
  Pose2 p = from;
  for (int i = 0; i < periods; ++i) {
    t.points.push_back({0.1 * i, p, {wheel, wheel}});
    p = integrateExact(p, toTwist({wheel, wheel}, robot), 0.1);
  }
  t.points.push_back({0.1 * periods, p, {}});
  return t;
}

TEST(PathSegment, StandsStillForOnePeriodOnlyWhereTheWheelsWouldJump) {
  const RobotDef robot;  // 4 rad/s per 0.1 s period
  const Trajectory forward = straight(robot, {0.5, 0.5, 0.0}, 3.0, 5);
  const Pose2 end = forward.points.back().pose;
  // 3 rad/s forward, then 3 rad/s backward: a jump of 6 rad/s needs a stop in between.
  const Trajectory back = straight(robot, end, -3.0, 5);
  const Trajectory joined = joinSegments({{forward, true}, {back, true}}, robot);
  ASSERT_EQ(joined.points.size(), forward.points.size() + back.points.size());
  EXPECT_EQ(joined.points[5].wheels, WheelSpeeds{});  // the stop
  EXPECT_NEAR(joined.duration(), 1.1, 1e-12);
  testing::expectConsistentWithLimits(joined, robot, {}, 1e-12);
  // 3 rad/s then 1 rad/s forward: within one step, joined directly.
  const Trajectory slower = straight(robot, end, 1.0, 5);
  const Trajectory direct = joinSegments({{forward, true}, {slower, true}}, robot);
  EXPECT_EQ(direct.points.size(), forward.points.size() + slower.points.size() - 1);
  EXPECT_NEAR(direct.duration(), 1.0, 1e-12);
  testing::expectConsistentWithLimits(direct, robot, {}, 1e-12);
}

TEST(PathSegment, CostOfPiecesEqualsCostOfTheJoinedTrajectory) {
  const RobotDef robot;
  const RotateTranslateRotateSteering steering(robot);
  const CostWeights w{1.5, 0.2};
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> pos(0.2, 1.5), ang(-kPi, kPi);
  int cusps = 0;
  for (int trial = 0; trial < 50; ++trial) {
    std::vector<PathSegment> plan;
    Pose2 at{pos(rng), pos(rng), ang(rng)};
    for (int k = 0; k < 6; ++k) {
      const Pose2 next{pos(rng), pos(rng), ang(rng)};
      plan.push_back({steering.steer(at, {}, next, SteerMode::kExact).trajectory, true});
      at = next;
    }
    const Trajectory joined = joinSegments(plan, robot);
    testing::expectConsistentWithLimits(joined, robot, {}, 1e-12);
    EXPECT_NEAR(segmentsCost(plan, robot, w), trajectoryCost(joined, robot, w), 1e-12);
    const MotionSummary m = summarizeMotion(joined, robot);
    EXPECT_EQ(m.cusps, joined.cusps(robot));
    EXPECT_NEAR(m.length_m, joined.pathLength(robot), 1e-12);
    cusps += m.cusps;
  }
  EXPECT_GT(cusps, 20);  // the junction rule was exercised
}

TEST(PathCost, WeighsReverseDrivingAndCusps) {
  const RobotDef robot;
  Trajectory t = straight(robot, {0.5, 0.5, 0.0}, 5.0, 10);  // 1 m/s * ... = 0.1 m forward
  const Trajectory back = straight(robot, t.points.back().pose, -2.5, 4);
  t = joinSegments({{t, true}, {back, true}}, robot);
  const MotionSummary m = summarizeMotion(t, robot);
  EXPECT_NEAR(m.length_m, 0.1 + 0.02, 1e-12);
  EXPECT_NEAR(m.reverse_m, 0.02, 1e-12);
  EXPECT_EQ(m.cusps, 1);
  EXPECT_EQ(m.first_direction, 1);
  EXPECT_EQ(m.last_direction, -1);
  EXPECT_NEAR(trajectoryCost(t, robot, {2.0, 0.3}), 0.12 + 2.0 * 0.02 + 0.3, 1e-12);
}

}  // namespace
}  // namespace parksim
