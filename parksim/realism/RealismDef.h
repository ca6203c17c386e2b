#pragma once
// How real the simulated robot is: every layer between the controller and the physics, each a
// definition with defaults and SI units, each switchable off. The presets (presetRealism):
//   ideal     today's robot: Bullet velocity motors, true pose at every physics step, the
//             nominal geometry (byte-identical results to parksim before realism existed);
//   lab       a small robot on a motion-capture table (sourced values, docs/realism.md);
//   odometry  no pose sensor, calibration errors, encoder dead reckoning.
// Random parts (calibration errors drawn within ranges, motor gains, sensor noise) come from
// the episode's noise seed (ExecutionDef::noise_seed), never from the planner's.

#include <string>
#include <vector>

#include "parksim/realism/Encoder.h"
#include "parksim/realism/Estimator.h"
#include "parksim/realism/MotorModel.h"
#include "parksim/realism/PoseSensor.h"
#include "parksim/realism/WheelSpeedLoop.h"

namespace parksim {

/// The robot as built against the nominal geometry the planner, controller and odometry use.
/// Each error is a fixed part plus a part drawn uniformly within +-range per episode, %.
struct CalibrationDef {
  double left_radius_error_pct = 0.0;
  double right_radius_error_pct = 0.0;
  /// Each wheel's radius error is drawn independently within this, %.
  double radius_error_range_pct = 0.0;
  double track_error_pct = 0.0;
  double track_error_range_pct = 0.0;
};

/// The high-level controller's loop: it reads the estimate and sends wheel-speed set-points.
struct ControlLoopDef {
  /// Ticks per second; 0: every physics step (the `ideal` loop).
  double rate_hz = 0.0;
  /// From reading the estimate to the set-points reaching the motors, s (computation and
  /// link); set-points are held until the next ones arrive.
  double latency_s = 0.0;
  /// After the plan, the robot counts as at rest only after standing still this long (at
  /// least ExecutionDef::rest_hold_s), s: a wheel loop stuck in the motors' static friction
  /// needs time to integrate past it, and ending the episode sooner would end it inside the
  /// friction's dead band.
  double settle_s = 0.0;
};

struct RealismDef {
  /// Preset it came from (for messages and metrics); "custom" once a layer is overridden.
  std::string name = "ideal";
  MotorDef motor;
  WheelSpeedLoopDef wheel_loop;
  CalibrationDef calibration;
  EncoderDef encoder;
  PoseSensorDef pose_sensor;
  EstimatorDef estimator;
  ControlLoopDef control;

  /// False for the ideal robot: every layer off (the episode then runs exactly the idealised
  /// model, and its files have no realism columns).
  bool active() const;
};

/// "ideal", "lab" or "odometry"; throws Error naming the choices otherwise.
RealismDef presetRealism(const std::string& name);
std::vector<std::string> realismPresetNames();
/// The names a run may ask for a realism by: "world" (the world file's realism: section, else
/// ideal), then every preset. `--realism`, the sweep spec's realism axis and episode requests
/// accept these.
std::vector<std::string> realismChoices();

/// Throws Error naming the first field out of range ("realism.motor.time_constant_s must be
/// positive").
void validateRealism(const RealismDef& def);

}  // namespace parksim
