#pragma once
// parksim's tracking controller ("tracking", the default Controller; a car's law is
// CarTracking.h): Kanayama et al., "A
// stable tracking control method for an autonomous mobile robot", ICRA 1990, adapted so that it
// also corrects while the plan turns in place or reverses: the heading term is not scaled by
// the reference speed.
//
// With the error e = (e_x, e_y, e_theta) of the reference pose in the robot's frame and the
// reference twist (v_r, omega_r):
//   v     = v_r cos(e_theta) + k_x e_x
//   omega = omega_r + k_y v_r e_y + k_theta sin(e_theta)
// Linearised, the along-track error decays at k_x and the cross-track/heading pair obeys
// s^2 + k_theta s + k_y v_r^2 = 0: stable for either sign of v_r. The result becomes wheel
// speeds scaled down together (keeping the curvature) when one exceeds the robot's limit.
//
// Gains follow the robot, its plan and its control loop (trackingGains): one bandwidth w for
// the along-track error (k_x = w) and for the heading loop at the plan's top speed v_top
// (k_y = w^2 / v_top^2, k_theta = 2 zeta w), so a robot of any size and speed gets the same
// error dynamics; w is at most 10 rad/s, and at most 2 pi / 25 of the control rate and 1/4 of
// the inverse latency, so the loop stays far from the rates at which a sampled, delayed loop
// loses its phase margin (docs/simulation.md).

#include "parksim/core/geometry/Pose2.h"
#include "parksim/core/model/DiffDrive.h"
#include "parksim/core/model/RobotDef.h"
#include "parksim/core/model/Trajectory.h"
#include "parksim/sim/control/CarTracking.h"
#include "parksim/sim/control/Controller.h"

namespace parksim {

/// Error of `reference` seen from `actual`: x forward, y to the left (m), heading (rad).
struct TrackingError {
  double along_m = 0.0;
  double cross_m = 0.0;
  double heading_rad = 0.0;
};

TrackingError trackingError(const Pose2& actual, const Pose2& reference);

/// Gains of the tracking law. Errors are those of the plan's pose at the same time, expressed
/// in the robot's frame.
struct TrackingGains {
  double k_x = 0.0;      ///< 1/s: forward speed per metre of along-track error
  double k_y = 0.0;      ///< 1/m^2: yaw rate per (m/s of reference speed x m of cross-track error)
  double k_theta = 0.0;  ///< 1/s: yaw rate per radian of heading error (sin e_theta)
};

/// The tracking controller's parameters ("tracking"; --controller-param NAME=VALUE).
struct TrackingDef {
  /// Error decay rate w, rad/s; 0: automatic, min(max_bandwidth_radps, 2 pi x control rate /
  /// 25, 0.25 / latency).
  double bandwidth_radps = 0.0;
  /// The automatic bandwidth's upper bound, rad/s.
  double max_bandwidth_radps = 10.0;
  /// Damping ratio zeta of the cross-track/heading loop at the design speed.
  double damping = 0.5;
  /// Speed the heading loop is tuned for, m/s; 0: the plan's top speed, at least 5 % of the
  /// robot's top speed (so a plan that barely moves gets bounded gains).
  double design_speed_mps = 0.0;
  /// A car (CarTracking.h): the lateral loop's bandwidth per metre travelled, 1/m; 0:
  /// automatic, min(2 / axle_distance, w / plan top speed).
  double car_path_bandwidth_1pm = 0.0;
  /// A car: the damping ratio of its lateral loop.
  double car_damping = 0.7;
};

/// The gains `def` gives for `robot` following a plan whose top reference-point speed is
/// `plan_top_speed_mps`, ticking every `period_s` with `latency_s`.
TrackingGains trackingGains(const TrackingDef& def, const RobotDef& robot,
                            double plan_top_speed_mps, double period_s, double latency_s);

/// Wheel speed commands that steer `actual` onto `reference` moving with `reference_twist`.
WheelSpeeds trackingCommand(const Pose2& actual, const Pose2& reference,
                            const Twist& reference_twist, const TrackingGains& gains,
                            const RobotDef& robot);

/// Scales both wheel speeds by the same factor so neither exceeds robot.max_wheel_speed_radps.
WheelSpeeds limitWheelSpeeds(const WheelSpeeds& wheels, const RobotDef& robot);

/// The tracking law as a Controller.
class TrackingController : public Controller {
 public:
  explicit TrackingController(const TrackingDef& def = {});

  void reset(const ControllerSetup& setup) override;
  WheelSpeeds command(const ControllerInput& input) override;
  /// A car's law (CarTracking.h).
  std::optional<CarCommand> carCommand(const ControllerInput& input) override;

  /// The gains reset() derived.
  const TrackingGains& gains() const { return gains_; }
  const CarTrackingGains& carGains() const { return car_gains_; }

 private:
  TrackingDef def_;
  RobotDef robot_;
  TrackingGains gains_;
  CarTrackingGains car_gains_;
};

/// The registry entry of "tracking" (ControllerRegistry.cpp lists it).
ControllerEntry trackingControllerEntry();

}  // namespace parksim
