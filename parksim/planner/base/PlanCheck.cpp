#include "parksim/planner/base/PlanCheck.h"

#include <algorithm>
#include <cmath>

#include "parksim/core/geometry/Angle.h"
#include "parksim/core/io/NumberFormat.h"
#include "parksim/core/model/DiffDrive.h"
#include "parksim/core/model/Geometry.h"

namespace parksim {

namespace {

std::string at(double t_s, const Pose2& pose) {
  return "at t = " + formatFixed(t_s, 3) + " s (x " + formatFixed(pose.x, 3) + " m, y " +
         formatFixed(pose.y, 3) + " m, " + formatFixed(radToDeg(pose.theta), 1) + " deg) ";
}

bool finite(const TrajectoryPoint& p) {
  return std::isfinite(p.t_s) && std::isfinite(p.pose.x) && std::isfinite(p.pose.y) &&
         std::isfinite(p.pose.theta) && std::isfinite(p.wheels.left_radps) &&
         std::isfinite(p.wheels.right_radps);
}

// Rounding forgiveness of the limit checks: plans timed exactly at a limit pass.
bool within(double value, double limit) { return std::abs(value) <= limit * (1.0 + 1e-9) + 1e-12; }

}  // namespace

std::optional<std::string> malformedPlan(const Trajectory& plan) {
  const std::vector<TrajectoryPoint>& pts = plan.points;
  if (pts.empty()) return "it has no rows";
  if (pts.size() > kMaxPlanRows) {
    return "it has " + std::to_string(pts.size()) + " rows, more than the limit of " +
           std::to_string(kMaxPlanRows);
  }
  for (std::size_t i = 0; i < pts.size(); ++i) {
    if (!finite(pts[i])) return "row " + std::to_string(i) + " holds a value that is not finite";
    if (i > 0 && !(pts[i].t_s > pts[i - 1].t_s)) {
      return "row " + std::to_string(i) + "'s time " + formatGeneral(pts[i].t_s, 9) +
             " s does not increase";
    }
  }
  return std::nullopt;
}

std::optional<PlanViolation> checkPlan(const Scenario& scenario, const FootprintChecker& checker,
                                       const Trajectory& plan,
                                       const MotionValidatorDef& requested) {
  const std::vector<TrajectoryPoint>& pts = plan.points;
  const RobotDef& robot = scenario.robot;
  const MotionValidatorDef validation = resolvedValidation(requested, robot);
  auto violation = [](const TrajectoryPoint& p, const std::string& what) {
    return PlanViolation{p.t_s, p.pose, at(p.t_s, p.pose) + what};
  };
  const TrajectoryPoint& first = pts.front();
  // Within the robot's motion-check step of the start (1 mm for the study's robot).
  if (positionDistance(first.pose, scenario.start) > motionCheckResolution(robot) ||
      headingDistance(first.pose, scenario.start) > degToRad(0.5)) {
    return violation(first, "the plan starts away from the world's start (x " +
                                formatFixed(scenario.start.x, 3) + " m, y " +
                                formatFixed(scenario.start.y, 3) + " m, " +
                                formatFixed(radToDeg(scenario.start.theta), 1) + " deg)");
  }
  const double radius = footprintRadius(robot);
  const double max_speed = robot.max_wheel_speed_radps;
  const double max_accel = robot.max_wheel_accel_radps2;
  WheelSpeeds before{};  // the robot starts at rest
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const TrajectoryPoint& p = pts[i];
    const bool last = i + 1 == pts.size();
    if (i > 0) {
      // Where the previous row's wheel speeds lead, against this row's pose.
      const TrajectoryPoint& q = pts[i - 1];
      const Pose2 reached = integrateExact(q.pose, toTwist(q.wheels, robot), p.t_s - q.t_s);
      const double jump =
          positionDistance(reached, p.pose) + headingDistance(reached, p.pose) * radius;
      if (jump > validation.resolution_m) {
        return violation(p, "the pose is " + formatGeneral(jump * 1e3, 3) +
                                " mm (footprint travel) from where the previous row's wheel "
                                "speeds lead; a plan's poses must follow its wheel speeds");
      }
    }
    // The last row's speeds are never driven: the plan ends there, at rest.
    const WheelSpeeds w = last ? WheelSpeeds{} : p.wheels;
    if (!within(w.left_radps, max_speed) || !within(w.right_radps, max_speed)) {
      return violation(p, "the wheel speeds (" + formatGeneral(w.left_radps, 4) + ", " +
                              formatGeneral(w.right_radps, 4) +
                              " rad/s) exceed robot.max_wheel_speed_radps " +
                              formatGeneral(max_speed));
    }
    // A step of the held speeds is within one acceleration step of the period it starts (or,
    // at the end, of the last period driven).
    const double period = last ? p.t_s - pts[i - 1].t_s : pts[i + 1].t_s - p.t_s;
    const double step = std::max(std::abs(w.left_radps - before.left_radps),
                                 std::abs(w.right_radps - before.right_radps));
    if (!within(step, max_accel * period)) {
      return violation(
          p, "a wheel's speed changes by " + formatGeneral(step, 4) + " rad/s in a " +
                 formatGeneral(period, 4) + "-s period: " + formatGeneral(step / period, 4) +
                 " rad/s^2 exceeds robot.max_wheel_accel_radps2 " + formatGeneral(max_accel));
    }
    before = w;
  }
  const MotionValidator validator(checker, robot, scenario.lot, validation);
  if (const std::optional<MotionValidator::Failure> f = validator.firstFailure(plan)) {
    const TrajectoryPoint p{f->t_s, f->pose, {}};
    if (f->outside_lot) {
      return violation(p,
                       "the robot's reference point leaves the lot (less half the motion "
                       "check's " +
                           formatGeneral(validation.resolution_m * 1e3, 3) + " mm resolution)");
    }
    const std::vector<std::string> names =
        checker.overlapping(f->pose, 0.5 * validation.resolution_m);
    std::string what = names.empty() ? std::string("an obstacle") : names.front();
    for (std::size_t k = 1; k < names.size(); ++k) what += ", " + names[k];
    return violation(p, "the footprint overlaps " + what);
  }
  const TrajectoryPoint& end = pts.back();
  const GoalRegion& goal = scenario.goal;
  const double pos = positionDistance(end.pose, goal.pose);
  const double heading = goalHeadingError(goal, end.pose.theta);
  if (!(pos <= goal.position_tolerance_m) || !(heading <= goal.heading_tolerance_rad)) {
    return violation(end, "the plan ends " + formatFixed(pos * 1e3, 3) + " mm / " +
                              formatFixed(radToDeg(heading), 3) +
                              " deg from the goal, outside its tolerance (" +
                              formatFixed(goal.position_tolerance_m * 1e3, 3) + " mm / " +
                              formatFixed(radToDeg(goal.heading_tolerance_rad), 3) + " deg)");
  }
  return std::nullopt;
}

}  // namespace parksim
