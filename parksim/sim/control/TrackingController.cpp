#include "parksim/sim/control/TrackingController.h"

#include <algorithm>
#include <cmath>

#include "parksim/core/geometry/Angle.h"
#include "parksim/core/io/Error.h"

namespace parksim {

TrackingError trackingError(const Pose2& actual, const Pose2& reference) {
  const double dx = reference.x - actual.x;
  const double dy = reference.y - actual.y;
  const double c = std::cos(actual.theta);
  const double s = std::sin(actual.theta);
  return {c * dx + s * dy, -s * dx + c * dy, angleDiff(reference.theta, actual.theta)};
}

TrackingGains trackingGains(const TrackingDef& def, const RobotDef& robot,
                            double plan_top_speed_mps, double period_s, double latency_s) {
  double w = def.bandwidth_radps;
  if (w <= 0.0) {
    w = def.max_bandwidth_radps;
    // A sampled loop: 25 ticks per radian of the error's rotation keeps the discrete poles
    // within a few percent of the continuous ones (w T = 0.25 at most).
    if (period_s > 0.0) w = std::min(w, 2.0 * kPi / (25.0 * period_s));
    // A delay L costs w L radians of phase at the crossover: 0.25 rad keeps ~75 of the
    // continuous loop's phase margin in degrees.
    if (latency_s > 0.0) w = std::min(w, 0.25 / latency_s);
  }
  const double top_speed = robot.max_wheel_speed_radps * robot.wheel_radius_m;
  const double v = def.design_speed_mps > 0.0 ? def.design_speed_mps
                                              : std::max(plan_top_speed_mps, 0.05 * top_speed);
  return {w, w * w / (v * v), 2.0 * def.damping * w};
}

WheelSpeeds trackingCommand(const Pose2& actual, const Pose2& reference,
                            const Twist& reference_twist, const TrackingGains& gains,
                            const RobotDef& robot) {
  const TrackingError e = trackingError(actual, reference);
  const double v_r = reference_twist.v_mps;
  const Twist command{v_r * std::cos(e.heading_rad) + gains.k_x * e.along_m,
                      reference_twist.omega_radps + gains.k_y * v_r * e.cross_m +
                          gains.k_theta * std::sin(e.heading_rad)};
  return limitWheelSpeeds(toWheelSpeeds(command, robot), robot);
}

WheelSpeeds limitWheelSpeeds(const WheelSpeeds& wheels, const RobotDef& robot) {
  const double largest = std::max(std::abs(wheels.left_radps), std::abs(wheels.right_radps));
  if (largest <= robot.max_wheel_speed_radps) return wheels;
  const double scale = robot.max_wheel_speed_radps / largest;
  return {wheels.left_radps * scale, wheels.right_radps * scale};
}

TrackingController::TrackingController(const TrackingDef& def) : def_(def) {}

void TrackingController::reset(const ControllerSetup& setup) {
  robot_ = setup.scenario.robot;
  double top = 0.0;
  for (const TrajectoryPoint& p : setup.plan.points) {
    top = std::max(top, std::abs(toTwist(p.wheels, robot_).v_mps));
  }
  gains_ = trackingGains(def_, robot_, top, setup.period_s, setup.latency_s);
  if (robot_.isCar()) {
    car_gains_ = carTrackingGains(def_, robot_, top, setup.period_s, setup.latency_s);
  }
}

WheelSpeeds TrackingController::command(const ControllerInput& in) {
  return trackingCommand(in.pose, in.reference, in.reference_twist, gains_, robot_);
}

std::optional<CarCommand> TrackingController::carCommand(const ControllerInput& in) {
  return carTrackingCommand(in.pose, in.reference, in.reference_twist.v_mps, in.reference_steer_rad,
                            car_gains_, robot_);
}

namespace {

void bind(TrackingDef& d, ParamSet& s) {
  s.add("bandwidth_radps", &d.bandwidth_radps,
        "error decay rate w, rad/s; 0: min(max_bandwidth_radps, 2 pi rate / 25, 0.25 / latency)",
        0.0, 1e4);
  s.add("max_bandwidth_radps", &d.max_bandwidth_radps, "the automatic bandwidth's bound, rad/s",
        1e-3, 1e4);
  s.add("damping", &d.damping, "damping ratio of the heading loop at the design speed", 0.05, 10.0);
  s.add("design_speed_mps", &d.design_speed_mps,
        "speed the heading loop is tuned for, m/s; 0: the plan's top speed", 0.0, 1e3);
  s.add("car_path_bandwidth_1pm", &d.car_path_bandwidth_1pm,
        "a car's lateral loop per metre travelled, 1/m; 0: min(2 / axle, w / top speed)", 0.0, 1e3);
  s.add("car_damping", &d.car_damping, "damping ratio of a car's lateral loop", 0.05, 10.0);
}

}  // namespace

ControllerEntry trackingControllerEntry() {
  ControllerInfo info;
  info.name = "tracking";
  info.description =
      "Kanayama tracking of the plan's pose and twist; gains from the robot, plan and loop";
  return controllerEntry<TrackingController>(std::move(info), TrackingDef{}, &bind);
}

}  // namespace parksim
