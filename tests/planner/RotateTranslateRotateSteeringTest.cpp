#include "parksim/planner/steering/RotateTranslateRotateSteering.h"

#include <random>

#include <gtest/gtest.h>

#include "parksim/core/io/Error.h"
#include "parksim/planner/base/PlanScenario.h"
#include "tests/support/PlanChecks.h"

namespace parksim {
namespace {

using testing::expectConsistentWithLimits;

TEST(RotateTranslateRotateSteering, ReachesTargetsExactlyWithinLimits) {
  const RobotDef robot;
  const RotateTranslateRotateSteering steering(robot);
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> pos(0.0, 1.5), ang(-kPi, kPi), wheel(-10.0, 10.0);
  int reversed = 0;
  for (int i = 0; i < 500; ++i) {
    const Pose2 from{pos(rng), pos(rng), ang(rng)};
    const Pose2 to{pos(rng), pos(rng), ang(rng)};
    // Half the cases start while moving: the robot brakes first.
    const WheelSpeeds arriving = i % 2 ? WheelSpeeds{wheel(rng), wheel(rng)} : WheelSpeeds{};
    for (SteerMode mode : {SteerMode::kToGoal, SteerMode::kExact}) {
      const SteerResult r = steering.steer(from, arriving, to, mode);
      ASSERT_TRUE(r.reached);
      EXPECT_EQ(r.trajectory.points.front().pose, from);
      EXPECT_EQ(r.trajectory.points.back().pose, to);
      expectConsistentWithLimits(r.trajectory, robot, arriving, 1e-12);
    }
    const SteerResult r = steering.steer(from, {}, to, SteerMode::kExact);
    for (const TrajectoryPoint& p : r.trajectory.points) {
      if (toTwist(p.wheels, robot).v_mps < -1e-9) {
        ++reversed;
        break;
      }
    }
  }
  EXPECT_GT(reversed, 100);  // targets behind are reached in reverse, turning less
}

TEST(RotateTranslateRotateSteering, PhasesAreInPlaceTurnsAndOneStraightLine) {
  const RobotDef robot;
  const RotateTranslateRotateSteering steering(robot);
  const Pose2 from{0.2, 0.3, 0.0}, to{0.8, 0.3, kPi / 2};
  const SteerResult r = steering.steer(from, {}, to, SteerMode::kExact);
  ASSERT_TRUE(r.reached);
  int phase_changes = 0;
  int last = 0;  // 1 translating, 2 turning
  for (std::size_t i = 0; i + 1 < r.trajectory.points.size(); ++i) {
    const Twist tw = toTwist(r.trajectory.points[i].wheels, robot);
    const bool turning = std::abs(tw.omega_radps) > 1e-12;
    const bool moving = std::abs(tw.v_mps) > 1e-12;
    ASSERT_FALSE(turning && moving) << "never both at once";
    const int phase = turning ? 2 : 1;
    if (last != 0 && phase != last) ++phase_changes;
    last = phase;
    if (moving) {
      EXPECT_NEAR(r.trajectory.points[i].pose.y, 0.3, 1e-12);
    }
  }
  EXPECT_EQ(phase_changes, 1);  // straight ahead, then one quarter turn at the end
  expectConsistentWithLimits(r.trajectory, robot, {}, 1e-12);
}

TEST(RotateTranslateRotateSteering, TurnsInPlaceWhenOnlyHeadingDiffers) {
  const RobotDef robot;
  const RotateTranslateRotateSteering steering(robot);
  const SteerResult r =
      steering.steer({1.0, 1.0, 0.0}, {}, {1.0, 1.0, degToRad(170)}, SteerMode::kExact);
  ASSERT_TRUE(r.reached);
  for (const TrajectoryPoint& p : r.trajectory.points) {
    EXPECT_EQ(p.pose.x, 1.0);
    EXPECT_EQ(p.pose.y, 1.0);
  }
  expectConsistentWithLimits(r.trajectory, robot, {}, 1e-12);
}

TEST(RotateTranslateRotateSteering, FixedHorizonCutsThePlanAndCarriesItsSpeed) {
  const RobotDef robot;
  const RotateTranslateRotateSteering steering(robot);
  const Pose2 from{0.1, 0.1, 0.0}, to{1.5, 0.1, 0.0};
  const SteerResult cut = steering.steer(from, {}, to, SteerMode::kFixedHorizon);
  EXPECT_FALSE(cut.reached);
  EXPECT_EQ(cut.trajectory.points.size(), 11u);
  EXPECT_NEAR(cut.trajectory.duration(), 1.0, 1e-12);
  expectConsistentWithLimits(cut.trajectory, robot, {}, 1e-12, /*final_stop=*/false);
  // The cut is the start of the full plan.
  const SteerResult full = steering.steer(from, {}, to, SteerMode::kExact);
  for (std::size_t i = 0; i + 1 < cut.trajectory.points.size(); ++i) {
    EXPECT_EQ(cut.trajectory.points[i], full.trajectory.points[i]);
  }
  // A short plan fits the horizon and ends on the target.
  const SteerResult near = steering.steer(from, {}, {0.12, 0.1, 0.0}, SteerMode::kFixedHorizon);
  EXPECT_TRUE(near.reached);
  EXPECT_EQ(near.trajectory.points.back().pose, (Pose2{0.12, 0.1, 0.0}));
}

TEST(RotateTranslateRotateSteering, RejectsBadDefinitions) {
  RotateTranslateRotateDef def;
  def.speed_fraction = 1.5;
  EXPECT_THROW(RotateTranslateRotateSteering(RobotDef{}, def), Error);
  def = {};
  def.period_s = 0.0;
  EXPECT_THROW(RotateTranslateRotateSteering(RobotDef{}, def), Error);
}

TEST(RotateTranslateRotateSteering, SetupsWithUnboundedProfilesAreRefusedBeforePlanning) {
  Scenario scenario;  // the study's lot and robot
  PlanSetup setup;
  // A tree planner steers across the whole lot, so the lot's diagonal bounds its moves (the A*
  // planners are bounded by the start-to-goal move instead: TimeAStarTest).
  setup.planner = "rrt";
  setup.steering_kind = SteeringKind::kRotateTranslateRotate;
  EXPECT_NO_THROW(checkPlanningLimits(scenario, setup));
  Scenario tiny_accel = scenario;
  tiny_accel.robot.max_wheel_accel_radps2 = 1e-6;  // braking alone: 1e8 periods
  EXPECT_THROW(checkPlanningLimits(tiny_accel, setup), Error);
  Scenario tiny_wheel = scenario;
  tiny_wheel.robot.wheel_radius_m = 1e-9;
  EXPECT_THROW(checkPlanningLimits(tiny_wheel, setup), Error);
  Scenario huge_lot = scenario;
  huge_lot.lot.x_max_m = huge_lot.lot.y_max_m = 1e6;
  EXPECT_THROW(checkPlanningLimits(huge_lot, setup), Error);
  // Move-to-pose trajectories are bounded by max_duration_s instead, whatever the lot.
  setup.steering_kind = SteeringKind::kMoveToPose;
  EXPECT_NO_THROW(checkPlanningLimits(huge_lot, setup));
}

}  // namespace
}  // namespace parksim
