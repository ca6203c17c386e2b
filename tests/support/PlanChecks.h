#pragma once
// Test support: the invariants every plan must satisfy, checked independently of the planner
// (exact integration, limits, an exact SAT footprint check finer than the validator's, goal).

#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "parksim/core/model/DiffDrive.h"
#include "parksim/core/model/Scenario.h"
#include "parksim/core/model/Trajectory.h"
#include "parksim/planner/base/PlanScenario.h"
#include "parksim/planner/motion/MotionValidator.h"
#include "parksim/planner/motion/PathCost.h"
#include "tests/support/StudyLot.h"

namespace parksim::testing {

/// Each point's wheel speeds, held for its period and integrated exactly, give the next pose
/// within `pose_tol_m` (and rad); wheel speeds stay within the speed limit and change by at
/// most one acceleration step per period, starting from `from_wheels` and, when `final_stop`,
/// including the step to zero at the end.
inline void expectConsistentWithLimits(const Trajectory& t, const RobotDef& robot,
                                       const WheelSpeeds& from_wheels = {},
                                       double pose_tol_m = 1e-9, bool final_stop = true) {
  ASSERT_FALSE(t.points.empty());
  WheelSpeeds prev = from_wheels;
  double dt = 0.0;
  for (std::size_t i = 0; i + 1 < t.points.size(); ++i) {
    const TrajectoryPoint& p = t.points[i];
    dt = t.points[i + 1].t_s - p.t_s;
    ASSERT_GT(dt, 0.0) << "point " << i;
    const Pose2 next = integrateExact(p.pose, toTwist(p.wheels, robot), dt);
    const Pose2& stored = t.points[i + 1].pose;
    ASSERT_NEAR(next.x, stored.x, pose_tol_m) << "point " << i;
    ASSERT_NEAR(next.y, stored.y, pose_tol_m) << "point " << i;
    ASSERT_NEAR(angleDiff(next.theta, stored.theta), 0.0, pose_tol_m) << "point " << i;
    const double max_step = robot.max_wheel_accel_radps2 * dt + 1e-9;
    ASSERT_LE(std::abs(p.wheels.left_radps), robot.max_wheel_speed_radps + 1e-9) << "point " << i;
    ASSERT_LE(std::abs(p.wheels.right_radps), robot.max_wheel_speed_radps + 1e-9) << "point " << i;
    ASSERT_LE(std::abs(p.wheels.left_radps - prev.left_radps), max_step) << "point " << i;
    ASSERT_LE(std::abs(p.wheels.right_radps - prev.right_radps), max_step) << "point " << i;
    prev = p.wheels;
  }
  EXPECT_EQ(t.points.back().wheels, WheelSpeeds{});
  if (final_stop && t.points.size() >= 2) {
    const double max_step = robot.max_wheel_accel_radps2 * dt + 1e-9;
    EXPECT_LE(std::abs(prev.left_radps), max_step) << "final stop";
    EXPECT_LE(std::abs(prev.right_radps), max_step) << "final stop";
  }
}

/// The exact footprint (no margin) is free at poses at most 0.2 mm of footprint travel apart,
/// by separating axes (not Bullet, not the planner's validator), and the reference point stays
/// in the lot.
inline void expectCollisionFree(const Scenario& s, const Trajectory& t) {
  const SatChecker exact(s);
  const double reach = footprintRadius(s.robot);
  for (std::size_t i = 0; i + 1 < t.points.size(); ++i) {
    const TrajectoryPoint& p = t.points[i];
    const double dt = t.points[i + 1].t_s - p.t_s;
    const Twist tw = toTwist(p.wheels, s.robot);
    const double travel = (std::abs(tw.v_mps) + std::abs(tw.omega_radps) * reach) * dt;
    const int n = std::max(1, static_cast<int>(std::ceil(travel / 0.0002)));
    for (int k = 0; k < n; ++k) {
      const Pose2 q = integrateExact(p.pose, tw, dt * k / n);
      ASSERT_TRUE(exact.isFree(q)) << "t=" << p.t_s + dt * k / n;
      ASSERT_TRUE(s.lot.contains(q.x, q.y)) << "t=" << p.t_s + dt * k / n;
    }
  }
  ASSERT_TRUE(exact.isFree(t.points.back().pose));
}

/// The last pose lies within the goal tolerance, of either heading when the goal accepts both.
inline void expectEndsInGoal(const GoalRegion& goal, const Trajectory& t) {
  ASSERT_FALSE(t.points.empty());
  const Pose2& end = t.points.back().pose;
  EXPECT_LE(positionDistance(end, goal.pose), goal.position_tolerance_m);
  double heading_error = headingDistance(end, goal.pose);
  if (goal.either_heading) heading_error = std::min(heading_error, kPi - heading_error);
  EXPECT_LE(heading_error, goal.heading_tolerance_rad);
}

/// Every invariant of a solved plan: (1) starts at the start pose, (2) consistent, (3) within
/// the wheel limits from rest to the final stop, across every junction, (4) accepted as a whole
/// by the motion validator (and free under the exact SAT check), (5) ends in the goal region;
/// and its reported cost is the cost of the returned trajectory (its path cost, or its duration
/// for planners that minimise duration).
inline void expectValidPlan(const Scenario& s, const FootprintChecker& checker,
                            const PlanSetup& setup, const PlanResult& r) {
  ASSERT_TRUE(r.solved()) << r.message;
  ASSERT_FALSE(r.trajectory.empty());
  EXPECT_EQ(r.trajectory.points.front().pose, s.start);
  EXPECT_EQ(r.trajectory.points.front().t_s, 0.0);
  expectConsistentWithLimits(r.trajectory, s.robot);
  const MotionValidator validator(checker, s.robot, s.lot, setup.validation);
  EXPECT_TRUE(validator.isValid(r.trajectory));
  expectCollisionFree(s, r.trajectory);
  expectEndsInGoal(s.goal, r.trajectory);
  const CostWeights w{setup.search.reverse_penalty, setup.search.cusp_penalty_m};
  EXPECT_NEAR(r.cost,
              r.objective == PlanObjective::kDuration ? r.trajectory.duration()
                                                      : trajectoryCost(r.trajectory, s.robot, w),
              1e-9);
  ASSERT_FALSE(r.cost_history.empty());
  EXPECT_NEAR(r.cost_history.back().cost, r.cost, 1e-9);
  EXPECT_GE(r.stats.first_solution_s, 0.0);
  EXPECT_GE(r.stats.first_solution_iteration, 0);
  EXPECT_EQ(r.waypoints.front(), s.start);
}

}  // namespace parksim::testing
