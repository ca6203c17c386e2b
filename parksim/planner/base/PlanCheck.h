#pragma once
// The check every plan parksim did not make itself gets before it is driven: a user planner's
// (a plugin's, a Python object's, a command's), in planScenario (PlanScenario.h) whatever front
// end plans, and a plan file's or array's, in the episode pipeline. parksim's own planners
// validate each trajectory as they build it (MotionValidator.h), so a differential drive's
// plans from them are not checked again; a car's plans are checked whoever made them. A plan that
// fails is never driven: the episode's verdict is plan_invalid, with the first offending time, pose
// and obstacle or limit (pipeline/Verdict.h).

#include <optional>
#include <string>

#include "parksim/core/model/FootprintChecker.h"
#include "parksim/core/model/Scenario.h"
#include "parksim/core/model/Trajectory.h"
#include "parksim/planner/motion/MotionValidator.h"

namespace parksim {

/// Most rows a plan may have (as a plan file: results/TrajectoryFile.h).
inline constexpr std::size_t kMaxPlanRows = 1'000'000;

/// How far a car's plan's curvature may exceed tan(max_steer) / axle_distance, and differ from
/// its steering angle's, relative to that limit: a millionth, the rounding of a curvature
/// computed from wheel speeds that were computed from a steering angle (and of a plan file's
/// speed and steering angle read back).
inline constexpr double kCarCurvatureSlack = 1e-6;

/// Why `plan` cannot even be checked, or nothing: no rows, more than kMaxPlanRows, a value that
/// is not finite, times that do not increase. For a planner's solved result this is the
/// planner's failure (planner_error), not a plan that merely breaks a rule.
std::optional<std::string> malformedPlan(const Trajectory& plan);

/// The first thing wrong with a plan, in time order of the checks below.
struct PlanViolation {
  double t_s = 0.0;    ///< on the plan's clock, s
  Pose2 pose;          ///< the pose there
  std::string reason;  ///< one line, e.g. "at t = 5.210 s (x 0.912 m, y 0.331 m, 87.0 deg)
                       ///< the footprint overlaps dropped_box"
};

/// Checks `plan` (well-formed: malformedPlan is empty) for `scenario`, returning its first
/// violation, or nothing when it may be driven:
/// - it starts at the world's start (within 0.5 deg and the robot's motion-check resolution,
///   motionCheckResolution: 1 mm for the study's robot);
/// - each row's pose is where the previous row's wheel speeds lead (within `validation`'s
///   resolution of footprint travel, by default the robot's): a plan is the exact integral of
///   its wheel speeds;
/// - a differential drive's wheel speeds within the robot's limit, and each change of a
///   wheel's speed (from rest at the start, to rest at the end) within the acceleration limit
///   times the row's period;
/// - a car's (RobotDef::isCar, docs/cars.md) rows: never turning in place; a moving row's
///   curvature its steering angle's, tan(steer) / axle_distance, and within the car's largest
///   (both to kCarCurvatureSlack); the steering angle within max_steer and, from straight
///   wheels at the start, changing by at most max_steer_rate times the period since the
///   previous row, moving or stopped; the speed within max_speed and, from rest at the start
///   to rest at the end, changing by at most max_accel times that period; a stop between
///   driving forward and in reverse (a gear change);
/// - no driven wheel needs more grip than it has (GripCheck.h);
/// - the swept footprint, without gaps, free of every obstacle and the reference point inside
///   the lot: the motion check parksim's planners use (MotionValidator.h, the same margin);
/// - it ends inside the goal region (position and heading tolerance).
/// Limits and tolerances are the robot's own, not the planning headroom's.
std::optional<PlanViolation> checkPlan(const Scenario& scenario, const FootprintChecker& checker,
                                       const Trajectory& plan,
                                       const MotionValidatorDef& validation = {});

}  // namespace parksim
