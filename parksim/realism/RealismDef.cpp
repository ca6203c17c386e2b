#include "parksim/realism/RealismDef.h"

#include <cmath>

#include "parksim/core/io/Error.h"

namespace parksim {

bool RealismDef::active() const {
  const CalibrationDef& c = calibration;
  return motor.enabled || pose_sensor.enabled || estimator.kind != EstimatorKind::kTruth ||
         control.rate_hz > 0.0 || control.latency_s > 0.0 || c.left_radius_error_pct != 0.0 ||
         c.right_radius_error_pct != 0.0 || c.radius_error_range_pct != 0.0 ||
         c.track_error_pct != 0.0 || c.track_error_range_pct != 0.0 ||
         encoder.counts_per_turn > 0.0 || encoder.noise_counts > 0.0;
}

std::vector<std::string> realismPresetNames() { return {"ideal", "lab", "odometry"}; }

std::vector<std::string> realismChoices() {
  std::vector<std::string> choices = realismPresetNames();
  choices.insert(choices.begin(), "world");
  return choices;
}

// Values and their sources: docs/realism.md.
RealismDef presetRealism(const std::string& name) {
  RealismDef r;
  r.name = name;
  if (name == "ideal") return r;
  if (name != "lab" && name != "odometry") {
    throw Error("unknown realism preset '" + name + "'; expected ideal, lab or odometry");
  }
  // Pololu micro metal gearmotor class (75:1 HPCB 12 V: 450 rpm, 1.0 kg cm stall), Romi
  // first-order fit (time constant 50 ms, start-up at ~8 % effort).
  r.motor.enabled = true;
  r.motor.stall_torque_nm = 0.098;
  r.motor.no_load_speed_radps = 47.1;
  r.motor.time_constant_s = 0.05;
  r.motor.startup_effort = 0.08;
  r.motor.rolling_resistance = 0.01;
  r.motor.supply_limit = 1.0;
  r.motor.gain_mismatch_pct = 3.0;
  // PI speed loop: ~20 ms closed-loop time constant on the robot (a lab DC servo with a P
  // speed loop: 20 ms), integral time 0.1 s.
  r.wheel_loop = {120.0, 0.06, 0.6};
  // Romi encoder: 12 CPR x 3952/33 = 1437.09 counts per wheel turn.
  r.encoder.counts_per_turn = 1437.09;
  if (name == "lab") {
    // Calibrated robot (UMBmark-class calibration): radius within +-0.2 %, track +-0.5 %.
    r.calibration.radius_error_range_pct = 0.2;
    r.calibration.track_error_range_pct = 0.5;
    // Motion capture: 100 Hz, 60 ms to the controller (Vicon -> ROS 50-60 ms), 0.5 mm and
    // 0.3 deg noise (Vicon dynamic error < 2 mm; Robotarium orientation noise 0.31 deg), 1 %
    // of frames lost.
    r.pose_sensor.enabled = true;
    r.pose_sensor.rate_hz = 100.0;
    r.pose_sensor.latency_s = 0.06;
    r.pose_sensor.position_noise_m = 5e-4;
    r.pose_sensor.heading_noise_rad = 0.3108 * 3.14159265358979323846 / 180.0;
    r.pose_sensor.dropout_probability = 0.01;
    r.estimator.kind = EstimatorKind::kFused;
  } else {
    // Uncalibrated robot, dead reckoning only: radius within +-1 % per wheel, track +-2 %.
    r.calibration.radius_error_range_pct = 1.0;
    r.calibration.track_error_range_pct = 2.0;
    r.estimator.kind = EstimatorKind::kOdometry;
  }
  // High-level control at 50 Hz (30-50 Hz typical), 5 ms computation and link.
  r.control.rate_hz = 50.0;
  r.control.latency_s = 0.005;
  r.control.settle_s = 2.0;
  return r;
}

void validateRealism(const RealismDef& d) {
  auto positive = [](double v, const char* field) {
    if (!(v > 0.0) || !std::isfinite(v)) {
      throw Error(std::string("realism.") + field + " must be positive");
    }
  };
  auto nonNegative = [](double v, const char* field) {
    if (!(v >= 0.0) || !std::isfinite(v)) {
      throw Error(std::string("realism.") + field + " must not be negative");
    }
  };
  if (d.motor.enabled) {
    positive(d.motor.stall_torque_nm, "motor.stall_torque_nm");
    positive(d.motor.no_load_speed_radps, "motor.no_load_speed_radps");
    positive(d.motor.time_constant_s, "motor.time_constant_s");
    nonNegative(d.motor.startup_effort, "motor.startup_effort");
    nonNegative(d.motor.rolling_resistance, "motor.rolling_resistance");
    positive(d.motor.supply_limit, "motor.supply_limit");
    nonNegative(d.motor.gain_mismatch_pct, "motor.gain_mismatch_pct");
    if (d.motor.startup_effort >= d.motor.supply_limit) {
      throw Error("realism.motor.startup_effort must be below motor.supply_limit");
    }
    if (d.motor.gain_mismatch_pct >= 100.0) {
      throw Error("realism.motor.gain_mismatch_pct must be below 100");
    }
    positive(d.wheel_loop.rate_hz, "wheel_loop.rate_hz");
    nonNegative(d.wheel_loop.kp, "wheel_loop.kp");
    nonNegative(d.wheel_loop.ki, "wheel_loop.ki");
  }
  const CalibrationDef& c = d.calibration;
  for (double v : {c.left_radius_error_pct, c.right_radius_error_pct, c.track_error_pct}) {
    if (!std::isfinite(v) || std::abs(v) >= 50.0) {
      throw Error("realism.calibration errors must lie within +-50 %");
    }
  }
  nonNegative(c.radius_error_range_pct, "calibration.radius_error_range_pct");
  nonNegative(c.track_error_range_pct, "calibration.track_error_range_pct");
  if (std::abs(c.left_radius_error_pct) + c.radius_error_range_pct >= 50.0 ||
      std::abs(c.right_radius_error_pct) + c.radius_error_range_pct >= 50.0 ||
      std::abs(c.track_error_pct) + c.track_error_range_pct >= 50.0) {
    throw Error("realism.calibration errors must lie within +-50 %");
  }
  nonNegative(d.encoder.counts_per_turn, "encoder.counts_per_turn");
  nonNegative(d.encoder.noise_counts, "encoder.noise_counts");
  if (d.pose_sensor.enabled) {
    positive(d.pose_sensor.rate_hz, "pose_sensor.rate_hz");
    nonNegative(d.pose_sensor.latency_s, "pose_sensor.latency_s");
    nonNegative(d.pose_sensor.position_noise_m, "pose_sensor.position_noise_m");
    nonNegative(d.pose_sensor.heading_noise_rad, "pose_sensor.heading_noise_rad");
    if (!(d.pose_sensor.dropout_probability >= 0.0 && d.pose_sensor.dropout_probability <= 1.0)) {
      throw Error("realism.pose_sensor.dropout_probability must lie in [0, 1]");
    }
  }
  if (d.estimator.kind == EstimatorKind::kFused && !d.pose_sensor.enabled) {
    throw Error("realism.estimator fused needs the pose sensor (realism.pose_sensor.enabled)");
  }
  positive(d.estimator.odometry_variance_per_m, "estimator.odometry_variance_per_m");
  if (d.estimator.history_steps < 1) throw Error("realism.estimator.history_steps must be >= 1");
  nonNegative(d.control.rate_hz, "control.rate_hz");
  nonNegative(d.control.latency_s, "control.latency_s");
  nonNegative(d.control.settle_s, "control.settle_s");
}

}  // namespace parksim
