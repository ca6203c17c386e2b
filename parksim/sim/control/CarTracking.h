#pragma once
// The tracking controller's law for a car (TrackingController.h's carCommand; docs/cars.md):
// the plan's speed and steering as feed-forward, and feedback on the along-track, cross-track
// and heading errors of the reference point (the rear axle's middle), forward and reverse.
//
// With the error e = (e_x, e_y, e_theta) of the reference pose in the car's frame, the plan's
// speed v_r and steering angle delta_r, and d the direction of travel (the sign of v_r, or of
// the commanded speed while v_r is 0):
//   v     = v_r cos(e_theta) + k_x e_x
//   kappa = tan(delta_r) / L + k_y e_y + k_theta d sin(e_theta)
//   delta = atan(L kappa)
// This is the Kanayama law of the differential drive (TrackingController.h) with its yaw-rate
// feedback divided by the speed: a law in distance rather than time. Linearised about the plan,
// the cross-track error along the path's length s obeys e'' + k_theta e' + k_y e = 0 in either
// direction of travel, so the car corrects over the same distance at any speed and while
// reversing, and the feedback asks no more steering at low speed than at high. Gains: one
// bandwidth per metre lambda (k_y = lambda^2, k_theta = 2 zeta lambda) and the differential
// drive's time bandwidth w for the along-track error (k_x = w).
//
// The steering's own rate limit makes the feed-forward the plan's angle a little ahead of time
// (ReferenceTrajectory::steerTargetAt), so the steering turns through each of the plan's changes
// centred on it.

#include "parksim/core/geometry/Pose2.h"
#include "parksim/core/model/RobotDef.h"
#include "parksim/sim/control/Controller.h"

namespace parksim {

struct TrackingDef;

/// Gains of the car's law.
struct CarTrackingGains {
  double k_x = 0.0;      ///< 1/s: speed per metre of along-track error
  double k_y = 0.0;      ///< 1/m^2: curvature per metre of cross-track error
  double k_theta = 0.0;  ///< 1/m: curvature per radian of heading error (sin e_theta)
};

/// The gains `def` gives for `car` following a plan whose top speed is `plan_top_speed_mps`,
/// ticking every `period_s` with `latency_s`: k_x as the differential drive's (trackingGains);
/// lambda = def.car_path_bandwidth_1pm, or automatically 2 / axle_distance (a correction over a
/// few of the car's lengths) and at most w / (plan top speed), so that the lateral loop is no
/// faster in time than the along-track one; zeta = def.car_damping.
CarTrackingGains carTrackingGains(const TrackingDef& def, const RobotDef& car,
                                  double plan_top_speed_mps, double period_s, double latency_s);

/// The command that steers `actual` onto `reference`, which moves at `reference_speed_mps` with
/// steering `reference_steer_rad`; speed and steering clamped to the car's limits.
CarCommand carTrackingCommand(const Pose2& actual, const Pose2& reference,
                              double reference_speed_mps, double reference_steer_rad,
                              const CarTrackingGains& gains, const RobotDef& car);

}  // namespace parksim
