#pragma once
// Differential-drive kinematics: unicycle model and the maps between body twist and wheel speeds.

#include "parksim/core/geometry/Pose2.h"
#include "parksim/core/model/RobotDef.h"

namespace parksim {

/// Body twist of the reference point.
struct Twist {
  double v_mps = 0.0;        ///< forward speed, m/s
  double omega_radps = 0.0;  ///< yaw rate, rad/s, counter-clockwise positive
};

/// Wheel angular speeds; positive drives the robot forward.
struct WheelSpeeds {
  double left_radps = 0.0;   ///< rad/s
  double right_radps = 0.0;  ///< rad/s

  friend bool operator==(const WheelSpeeds&, const WheelSpeeds&) = default;
};

/// (v, omega) -> (omega_left, omega_right).
WheelSpeeds toWheelSpeeds(const Twist& twist, const RobotDef& robot);

/// (omega_left, omega_right) -> (v, omega).
Twist toTwist(const WheelSpeeds& wheels, const RobotDef& robot);

/// Exact solution of the unicycle model for a twist held constant over dt_s seconds
/// (a circular arc, or a straight segment when omega is zero).
Pose2 integrateExact(const Pose2& pose, const Twist& twist, double dt_s);

/// Largest wheel speed magnitude of a twist, rad/s.
double maxWheelSpeed(const Twist& twist, const RobotDef& robot);

}  // namespace parksim
