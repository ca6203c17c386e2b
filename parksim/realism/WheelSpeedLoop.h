#pragma once
// The motor board's wheel-speed loop: a PI controller at its own rate that turns a wheel-speed
// set-point into motor effort, with the set-point's back-EMF as feed-forward
// (set-point / no-load speed) and an integrator clamped to the supply (no wind-up). It measures
// the wheel's speed as the encoder's count difference over its period, as firmware does.

namespace parksim {

struct WheelSpeedLoopDef {
  /// Rate of the loop, Hz; it runs every round(physics rate / rate) physics steps (at least 1).
  double rate_hz = 120.0;
  /// Effort per rad/s of speed error.
  double kp = 0.06;
  /// Effort per rad of integrated speed error (per rad/s per s).
  double ki = 0.6;
};

class WheelSpeedLoop {
 public:
  /// `no_load_speed_radps` of the nominal motor (feed-forward), `supply_limit` clamps effort.
  WheelSpeedLoop(const WheelSpeedLoopDef& def, double no_load_speed_radps, double supply_limit);

  /// One tick: effort for `setpoint_radps` given the measured speed; `period_s` since the last
  /// tick.
  double update(double setpoint_radps, double measured_radps, double period_s);
  double effort() const { return effort_; }

 private:
  WheelSpeedLoopDef def_;
  double no_load_;
  double limit_;
  double integral_ = 0.0;
  double effort_ = 0.0;
};

}  // namespace parksim
