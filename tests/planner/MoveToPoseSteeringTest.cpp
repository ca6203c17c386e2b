#include "parksim/planner/steering/MoveToPoseSteering.h"

#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "parksim/core/io/Error.h"
#include "tests/support/PlanChecks.h"

namespace parksim {
namespace {

// Every point's wheel speeds, held for its period and integrated exactly, give the next pose;
// speed and acceleration limits hold, starting from `from_wheels`.
void expectConsistent(const Trajectory& t, const RobotDef& robot, const WheelSpeeds& from_wheels,
                      double dt) {
  ASSERT_GE(t.points.size(), 1u);
  WheelSpeeds prev = from_wheels;
  const double max_step = robot.max_wheel_accel_radps2 * dt + 1e-12;
  for (std::size_t i = 0; i + 1 < t.points.size(); ++i) {
    const TrajectoryPoint& p = t.points[i];
    const Pose2 next = integrateExact(p.pose, toTwist(p.wheels, robot), dt);
    EXPECT_NEAR(next.x, t.points[i + 1].pose.x, 1e-12);
    EXPECT_NEAR(next.y, t.points[i + 1].pose.y, 1e-12);
    EXPECT_NEAR(angleDiff(next.theta, t.points[i + 1].pose.theta), 0.0, 1e-12);
    EXPECT_NEAR(t.points[i + 1].t_s - p.t_s, dt, 1e-12);
    EXPECT_LE(std::abs(p.wheels.left_radps), robot.max_wheel_speed_radps + 1e-12);
    EXPECT_LE(std::abs(p.wheels.right_radps), robot.max_wheel_speed_radps + 1e-12);
    EXPECT_LE(std::abs(p.wheels.left_radps - prev.left_radps), max_step);
    EXPECT_LE(std::abs(p.wheels.right_radps - prev.right_radps), max_step);
    prev = p.wheels;
  }
  EXPECT_EQ(t.points.back().wheels, WheelSpeeds{});
}

TEST(MoveToPoseSteering, FixedHorizonLastsOneSecond) {
  const RobotDef robot;
  const MoveToPoseSteering steering(robot);
  const SteerResult r =
      steering.steer({0.1, 0.1, kPi / 2}, {}, {1.0, 0.8, 0.0}, SteerMode::kFixedHorizon);
  EXPECT_FALSE(r.reached);
  EXPECT_EQ(r.trajectory.points.size(), 11u);
  EXPECT_NEAR(r.trajectory.duration(), 1.0, 1e-12);
  expectConsistent(r.trajectory, robot, {}, 0.1);
}

TEST(MoveToPoseSteering, ToGoalEndsWithinOneMillimetreAndHalfADegree) {
  const RobotDef robot;
  const MoveToPoseSteering steering(robot);
  std::mt19937_64 rng(42);
  std::uniform_real_distribution<double> pos(0.0, 1.5), ang(-kPi, kPi);
  int reversed = 0;
  for (int i = 0; i < 300; ++i) {
    const Pose2 from{pos(rng), pos(rng), ang(rng)};
    const Pose2 to{pos(rng), pos(rng), ang(rng)};
    const SteerResult r = steering.steer(from, {}, to, SteerMode::kToGoal);
    ASSERT_TRUE(r.reached) << "case " << i;
    const Pose2& end = r.trajectory.points.back().pose;
    EXPECT_LE(positionDistance(end, to), 0.001);
    EXPECT_LE(headingDistance(end, to), degToRad(0.5));
    expectConsistent(r.trajectory, robot, {}, 0.1);
    if (toTwist(r.trajectory.points.front().wheels, robot).v_mps < 0.0) ++reversed;
  }
  EXPECT_GT(reversed, 50);  // targets behind the robot are approached in reverse
}

TEST(MoveToPoseSteering, ToGoalEndsWithALegalStop) {
  const RobotDef robot;
  const MoveToPoseSteering steering(robot);
  std::mt19937_64 rng(43);
  std::uniform_real_distribution<double> pos(0.0, 1.5), ang(-kPi, kPi), wheel(-10.0, 10.0);
  for (int i = 0; i < 300; ++i) {
    const Pose2 from{pos(rng), pos(rng), ang(rng)};
    const Pose2 to{pos(rng), pos(rng), ang(rng)};
    const WheelSpeeds arriving{wheel(rng), wheel(rng)};
    const SteerResult r = steering.steer(from, arriving, to, SteerMode::kToGoal);
    ASSERT_TRUE(r.reached) << "case " << i;
    testing::expectConsistentWithLimits(r.trajectory, robot, arriving, 1e-12);
  }
}

TEST(MoveToPoseSteering, ExactModeEndsOnTheTargetItself) {
  const RobotDef robot;
  const MoveToPoseSteering steering(robot);
  std::mt19937_64 rng(44);
  std::uniform_real_distribution<double> pos(0.0, 1.5), ang(-kPi, kPi), wheel(-10.0, 10.0);
  for (int i = 0; i < 300; ++i) {
    const Pose2 from{pos(rng), pos(rng), ang(rng)};
    const Pose2 to{pos(rng), pos(rng), ang(rng)};
    const WheelSpeeds arriving = i % 2 ? WheelSpeeds{wheel(rng), wheel(rng)} : WheelSpeeds{};
    const SteerResult exact = steering.steer(from, arriving, to, SteerMode::kExact);
    ASSERT_TRUE(exact.reached) << "case " << i;
    EXPECT_EQ(exact.trajectory.points.front().pose, from);
    EXPECT_EQ(exact.trajectory.points.back().pose, to);
    testing::expectConsistentWithLimits(exact.trajectory, robot, arriving, 1e-12);
    // The controller drives the approach; the finisher only closes the last fraction of a
    // millimetre and turns to the heading, as the controller would have turned in place.
    const SteerResult approx = steering.steer(from, arriving, to, SteerMode::kToGoal);
    double turn_exact = 0.0, turn_approx = 0.0;
    for (std::size_t k = 0; k + 1 < exact.trajectory.points.size(); ++k) {
      turn_exact += std::abs(toTwist(exact.trajectory.points[k].wheels, robot).omega_radps) * 0.1;
    }
    for (std::size_t k = 0; k + 1 < approx.trajectory.points.size(); ++k) {
      turn_approx += std::abs(toTwist(approx.trajectory.points[k].wheels, robot).omega_radps) * 0.1;
    }
    EXPECT_LE(turn_exact, turn_approx + degToRad(1.0)) << "case " << i;
    EXPECT_NEAR(exact.trajectory.pathLength(robot), approx.trajectory.pathLength(robot), 0.002);
  }
}

TEST(MoveToPoseSteering, TargetBehindIsReachedInReverse) {
  const RobotDef robot;
  const MoveToPoseSteering steering(robot);
  const SteerResult r = steering.steer({1.0, 1.0, 0.0}, {}, {0.7, 1.0, 0.0}, SteerMode::kToGoal);
  ASSERT_TRUE(r.reached);
  for (std::size_t i = 0; i + 1 < r.trajectory.points.size(); ++i) {
    EXPECT_LE(toTwist(r.trajectory.points[i].wheels, robot).v_mps, 1e-12);
  }
  EXPECT_NEAR(r.trajectory.points.back().pose.x, 0.7, 0.001);
  expectConsistent(r.trajectory, robot, {}, 0.1);
}

TEST(MoveToPoseSteering, AccelerationLimitStartsFromArrivalSpeeds) {
  const RobotDef robot;
  const MoveToPoseSteering steering(robot);
  const WheelSpeeds arriving{8.0, 8.0};  // moving forward fast
  const SteerResult r =
      steering.steer({1.0, 1.0, 0.0}, arriving, {0.6, 1.0, 0.0}, SteerMode::kToGoal);
  ASSERT_TRUE(r.reached);
  expectConsistent(r.trajectory, robot, arriving, 0.1);
  // It has to brake before reversing: the first command still drives forward.
  EXPECT_GT(toTwist(r.trajectory.points.front().wheels, robot).v_mps, 0.0);
}

TEST(MoveToPoseSteering, GivesUpInBoundedTime) {
  const RobotDef robot;
  MoveToPoseDef def;
  def.max_duration_s = 2.0;
  const MoveToPoseSteering steering(robot, def);
  const SteerResult r = steering.steer({0.0, 0.0, 0.0}, {}, {1.5, 1.0, kPi}, SteerMode::kToGoal);
  EXPECT_FALSE(r.reached);
  EXPECT_EQ(r.trajectory.points.size(), 21u);
}

TEST(MoveToPoseSteering, TurnsInPlaceWhenOnlyHeadingDiffers) {
  const RobotDef robot;
  const MoveToPoseSteering steering(robot);
  const SteerResult r =
      steering.steer({1.0, 1.0, 0.0}, {}, {1.0, 1.0, degToRad(120)}, SteerMode::kToGoal);
  ASSERT_TRUE(r.reached);
  for (const TrajectoryPoint& p : r.trajectory.points) {
    EXPECT_NEAR(p.pose.x, 1.0, 1e-12);
    EXPECT_NEAR(p.pose.y, 1.0, 1e-12);
  }
}

TEST(MoveToPoseSteering, RejectsUnstableGains) {
  MoveToPoseDef def;
  def.k_beta = 0.3;
  EXPECT_THROW(MoveToPoseSteering(RobotDef{}, def), Error);
}

}  // namespace
}  // namespace parksim
