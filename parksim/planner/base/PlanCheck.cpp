#include "parksim/planner/base/PlanCheck.h"

#include <algorithm>
#include <cmath>

#include "parksim/core/geometry/Angle.h"
#include "parksim/core/io/NumberFormat.h"
#include "parksim/core/model/DiffDrive.h"
#include "parksim/core/model/Geometry.h"
#include "parksim/planner/base/GripCheck.h"

namespace parksim {

namespace {

std::string at(double t_s, const Pose2& pose) {
  return "at t = " + formatFixed(t_s, 3) + " s (x " + formatFixed(pose.x, 3) + " m, y " +
         formatFixed(pose.y, 3) + " m, " + formatFixed(radToDeg(pose.theta), 1) + " deg) ";
}

bool finite(const TrajectoryPoint& p) {
  return std::isfinite(p.t_s) && std::isfinite(p.pose.x) && std::isfinite(p.pose.y) &&
         std::isfinite(p.pose.theta) && std::isfinite(p.wheels.left_radps) &&
         std::isfinite(p.wheels.right_radps) && std::isfinite(p.steer_rad);
}

// Rounding forgiveness of the limit checks: plans timed exactly at a limit pass.
bool within(double value, double limit) { return std::abs(value) <= limit * (1.0 + 1e-9) + 1e-12; }

std::string num(double v) { return formatGeneral(v, 4); }

// A differential drive's limits: each wheel's speed, and each change of it (from rest at the
// start, to rest at the end) within the acceleration limit times the row's period.
std::optional<std::string> wheelLimitProblem(const RobotDef& robot,
                                             const std::vector<TrajectoryPoint>& pts, std::size_t i,
                                             WheelSpeeds& before) {
  const TrajectoryPoint& p = pts[i];
  const bool last = i + 1 == pts.size();
  const double max_speed = robot.max_wheel_speed_radps;
  const double max_accel = robot.max_wheel_accel_radps2;
  // The last row's speeds are never driven: the plan ends there, at rest.
  const WheelSpeeds w = last ? WheelSpeeds{} : p.wheels;
  if (!within(w.left_radps, max_speed) || !within(w.right_radps, max_speed)) {
    return "the wheel speeds (" + formatGeneral(w.left_radps, 4) + ", " +
           formatGeneral(w.right_radps, 4) + " rad/s) exceed robot.max_wheel_speed_radps " +
           formatGeneral(max_speed);
  }
  // A step of the held speeds is within one acceleration step of the period it starts (or,
  // at the end, of the last period driven).
  const double period = last ? p.t_s - pts[i - 1].t_s : pts[i + 1].t_s - p.t_s;
  const double step = std::max(std::abs(w.left_radps - before.left_radps),
                               std::abs(w.right_radps - before.right_radps));
  if (!within(step, max_accel * period)) {
    return "a wheel's speed changes by " + formatGeneral(step, 4) + " rad/s in a " +
           formatGeneral(period, 4) + "-s period: " + formatGeneral(step / period, 4) +
           " rad/s^2 exceeds robot.max_wheel_accel_radps2 " + formatGeneral(max_accel);
  }
  before = w;
  return std::nullopt;
}

// Where a car's plan stands: its steering angle, speed and gear after the previous row.
struct CarState {
  double steer_rad = 0.0;  ///< wheels straight at the start
  double v_mps = 0.0;      ///< at rest at the start
  int gear = 0;            ///< +1 forward, -1 reverse, 0 not yet moved
};

// A car's limits (docs/cars.md): it never turns in place; a moving row's curvature is its
// steering angle's, tan(steer) / axle_distance, within the car's largest (kCarCurvatureSlack);
// the steering angle within max_steer and changing by at most max_steer_rate times the period
// since the previous row, moving or not; the speed within max_speed and changing by at most
// max_accel times that period (from rest at the start, to rest at the end); and a gear change
// stops. A row's change from the previous one takes the period between them, the first row's
// (from straight wheels, at rest) the period it starts.
std::optional<std::string> carLimitProblem(const RobotDef& car,
                                           const std::vector<TrajectoryPoint>& pts, std::size_t i,
                                           CarState& before) {
  const TrajectoryPoint& p = pts[i];
  const bool last = i + 1 == pts.size();
  const double period = i > 0 ? p.t_s - pts[i - 1].t_s : (last ? 0.0 : pts[i + 1].t_s - p.t_s);
  const Twist tw = toTwist(p.wheels, car);
  // The last row is never driven: the plan ends there, at rest.
  const double v = last ? 0.0 : tw.v_mps;
  const double omega = last ? 0.0 : tw.omega_radps;
  const bool moving = std::abs(v) > kCarStillFraction * car.max_speed_mps;
  const double kappa_max = car.maxCurvature();
  const std::string limits = " (robot.max_steer_deg " + num(radToDeg(car.max_steer_rad)) +
                             ", robot.axle_distance " + num(car.axle_distance_m) + " m)";
  if (!moving && std::abs(omega) > 1e-12) {
    return "the car turns in place: yaw rate " + num(omega) + " rad/s at speed " + num(v) +
           " m/s; a car turns only while it moves, by at most tan(max_steer) / axle_distance = " +
           num(kappa_max) + " 1/m of its path" + limits;
  }
  if (moving) {
    const double kappa = omega / v;
    if (std::abs(kappa) > kappa_max * (1.0 + kCarCurvatureSlack)) {
      return "the curvature " + num(kappa) + " 1/m (radius " + num(1.0 / std::abs(kappa)) +
             " m) exceeds the car's tan(max_steer) / axle_distance = " + num(kappa_max) +
             " 1/m (radius " + num(car.minTurningRadius()) + " m)" + limits;
    }
    const double steered = std::tan(p.steer_rad) / car.axle_distance_m;
    if (std::abs(steered - kappa) > kappa_max * kCarCurvatureSlack) {
      return "the curvature " + num(kappa) + " 1/m of the wheel speeds is not the steering " +
             "angle's: tan(" + num(p.steer_rad) + " rad) / axle_distance = " + num(steered) +
             " 1/m";
    }
  }
  if (!within(p.steer_rad, car.max_steer_rad)) {
    return "the steering angle " + num(p.steer_rad) + " rad (" + num(radToDeg(p.steer_rad)) +
           " deg) exceeds robot.max_steer_deg " + num(radToDeg(car.max_steer_rad));
  }
  const double steer_step = std::abs(p.steer_rad - before.steer_rad);
  if (!within(steer_step, car.max_steer_rate_radps * period)) {
    return "the steering angle changes by " + num(steer_step) + " rad in " + num(period) +
           " s: " + num(steer_step / period) + " rad/s exceeds robot.max_steer_rate_degps " +
           num(radToDeg(car.max_steer_rate_radps)) + " (" + num(car.max_steer_rate_radps) +
           " rad/s; steering while stopped takes time too)";
  }
  if (!within(v, car.max_speed_mps)) {
    return "the speed " + num(v) + " m/s exceeds robot.max_speed_mps " + num(car.max_speed_mps);
  }
  const double speed_step = std::abs(v - before.v_mps);
  if (!within(speed_step, car.max_accel_mps2 * period)) {
    return "the speed changes by " + num(speed_step) + " m/s in " + num(period) +
           " s: " + num(speed_step / period) + " m/s^2 exceeds robot.max_accel_mps2 " +
           num(car.max_accel_mps2);
  }
  if (moving) {
    const int gear = v > 0.0 ? 1 : -1;
    if (before.gear == -gear && std::abs(before.v_mps) > kCarStillFraction * car.max_speed_mps) {
      return std::string("the car changes gear from ") +
             (gear > 0 ? "reverse to forward" : "forward to reverse") +
             " without stopping (speed " + num(before.v_mps) + " m/s, then " + num(v) +
             " m/s); a gear change stops";
    }
    before.gear = gear;
  }
  before.steer_rad = p.steer_rad;
  before.v_mps = v;
  return std::nullopt;
}

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
  WheelSpeeds wheels_before{};  // the robot starts at rest
  CarState car_before;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const TrajectoryPoint& p = pts[i];
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
    const std::optional<std::string> problem =
        robot.isCar() ? carLimitProblem(robot, pts, i, car_before)
                      : wheelLimitProblem(robot, pts, i, wheels_before);
    if (problem) return violation(p, *problem);
  }
  if (std::optional<PlanViolation> slip = gripViolation(scenario, plan)) return slip;
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
