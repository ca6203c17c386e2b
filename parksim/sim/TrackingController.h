#pragma once
// Closed-loop tracking of a planned trajectory (Kanayama et al., "A stable tracking control
// method for an autonomous mobile robot", ICRA 1990), adapted so that it also corrects while
// the plan turns in place or reverses: the heading term is not scaled by the reference speed.
//
// With the error e = (e_x, e_y, e_theta) of the reference pose in the robot's frame and the
// reference twist (v_r, omega_r):
//   v     = v_r cos(e_theta) + k_x e_x
//   omega = omega_r + k_y v_r e_y + k_theta sin(e_theta)
// Linearised, the cross-track/heading error obeys s^2 + k_theta s + k_y v_r^2 = 0: stable for
// either sign of v_r. The result becomes wheel speeds scaled down together (keeping the
// curvature) when one exceeds the robot's limit.

#include "parksim/core/DiffDrive.h"
#include "parksim/core/Pose2.h"
#include "parksim/core/RobotDef.h"
#include "parksim/sim/ExecutionDef.h"

namespace parksim {

/// Error of `reference` seen from `actual`: x forward, y to the left (m), heading (rad).
struct TrackingError {
  double along_m = 0.0;
  double cross_m = 0.0;
  double heading_rad = 0.0;
};

TrackingError trackingError(const Pose2& actual, const Pose2& reference);

/// Wheel speed commands that steer `actual` onto `reference` moving with `reference_twist`.
WheelSpeeds trackingCommand(const Pose2& actual, const Pose2& reference,
                            const Twist& reference_twist, const TrackingGains& gains,
                            const RobotDef& robot);

/// Scales both wheel speeds by the same factor so neither exceeds robot.max_wheel_speed_radps.
WheelSpeeds limitWheelSpeeds(const WheelSpeeds& wheels, const RobotDef& robot);

}  // namespace parksim
