#pragma once
// A brushed DC gear-motor driving one wheel: the linear torque-speed line between stall torque
// and no-load speed, scaled by the effort (the driver's PWM duty, -1..1, clamped to the supply),
// with a drive-train Coulomb friction that the effort must overcome before the wheel moves.
//
//   torque = stall_torque * (gain * clamp(effort, -supply, supply) - omega / no_load_speed)
//
// The first-order lag is the motor's own mechanics: an unloaded motor with the torque-speed
// line above and axle inertia J settles with time constant J * no_load_speed / stall_torque,
// so the model gives the wheel axle the inertia that makes it time_constant_s
// (axleInertia()). On the robot the load adds inertia: the robot's time constant is longer,
// as on real robots (tests/sim predict it).

#include <random>

namespace parksim {

struct MotorDef {
  /// Off: the wheels are Bullet's ideal velocity motors (the `ideal` robot).
  bool enabled = false;
  /// Torque at zero speed and full effort, N m (at the wheel, after the gearbox).
  double stall_torque_nm = 0.098;
  /// Speed at full effort and no load, rad/s (at the wheel).
  double no_load_speed_radps = 47.1;
  /// Time constant of the unloaded motor, s.
  double time_constant_s = 0.05;
  /// Share of full effort needed to start the wheel turning (static/Coulomb friction of the
  /// drive train), 0..1.
  double startup_effort = 0.08;
  /// Rolling resistance coefficient (resistance force / normal force); its torque at the
  /// wheel, coefficient x half the robot's weight x radius, adds to the drive-train friction.
  double rolling_resistance = 0.0;
  /// Largest effort magnitude the supply allows, 0..1 (battery sag below 1).
  double supply_limit = 1.0;
  /// Left/right gain mismatch: each motor's gain is drawn uniformly in 1 +- this, %.
  double gain_mismatch_pct = 0.0;
};

class MotorModel {
 public:
  /// `gain` multiplies the effort (1: the nominal motor).
  MotorModel(const MotorDef& def, double gain);

  /// Drive torque at the wheel for `effort` (clamped to the supply) at wheel speed omega, N m.
  /// The drive-train friction is not included (frictionTorque()).
  double torque(double effort, double omega_radps) const;

  /// Moment of inertia about the axle that makes the unloaded time constant time_constant_s,
  /// kg m^2.
  double axleInertia() const;
  /// Coulomb friction torque of the drive train (start-up effort), N m.
  double frictionTorque() const;
  double gain() const { return gain_; }
  const MotorDef& def() const { return def_; }

 private:
  MotorDef def_;
  double gain_;
};

/// The gain of one motor drawn within def.gain_mismatch_pct (1 when it is 0).
double drawMotorGain(const MotorDef& def, std::mt19937_64& rng);

}  // namespace parksim
