#include "parksim/sim/TrackingController.h"

#include <algorithm>
#include <cmath>

#include "parksim/core/Angle.h"

namespace parksim {

TrackingError trackingError(const Pose2& actual, const Pose2& reference) {
  const double dx = reference.x - actual.x;
  const double dy = reference.y - actual.y;
  const double c = std::cos(actual.theta);
  const double s = std::sin(actual.theta);
  return {c * dx + s * dy, -s * dx + c * dy, angleDiff(reference.theta, actual.theta)};
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

}  // namespace parksim
