#include "parksim/core/model/DiffDrive.h"

#include <algorithm>
#include <cmath>

namespace parksim {

WheelSpeeds toWheelSpeeds(const Twist& twist, const RobotDef& robot) {
  const double half_track = 0.5 * robot.wheel_base_m;
  return {(twist.v_mps - twist.omega_radps * half_track) / robot.wheel_radius_m,
          (twist.v_mps + twist.omega_radps * half_track) / robot.wheel_radius_m};
}

Twist toTwist(const WheelSpeeds& wheels, const RobotDef& robot) {
  const double r = robot.wheel_radius_m;
  return {0.5 * r * (wheels.left_radps + wheels.right_radps),
          r * (wheels.right_radps - wheels.left_radps) / robot.wheel_base_m};
}

Pose2 integrateExact(const Pose2& pose, const Twist& twist, double dt_s) {
  const double dtheta = twist.omega_radps * dt_s;
  const double ds = twist.v_mps * dt_s;
  // Chord form: the arc's chord has length ds * sinc(dtheta / 2) and points along the mean heading.
  // It is exact for any dtheta and well conditioned as dtheta -> 0, unlike v/omega * (sin - sin).
  const double half = 0.5 * dtheta;
  const double sinc = std::abs(half) < 1e-6 ? 1.0 - half * half / 6.0 : std::sin(half) / half;
  const double chord = ds * sinc;
  const double mid = pose.theta + half;
  return {pose.x + chord * std::cos(mid), pose.y + chord * std::sin(mid),
          wrapAngle(pose.theta + dtheta)};
}

double maxWheelSpeed(const Twist& twist, const RobotDef& robot) {
  const WheelSpeeds w = toWheelSpeeds(twist, robot);
  return std::max(std::abs(w.left_radps), std::abs(w.right_radps));
}

}  // namespace parksim
