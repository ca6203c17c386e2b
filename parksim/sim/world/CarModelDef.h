#pragma once
// The parts of a simulated car (RobotDef::isCar; sim/CarBody.h) that the world file does not
// describe: its tyres' give and its steering servo. Bullet-free.

namespace parksim {

struct CarModelDef {
  /// Each wheel's ground contact yields by this fraction of the wheel radius under a quarter
  /// of the car's weight (5 mm for a 0.33 m wheel), critically damped: a tyre and suspension
  /// in one spring. A body on four rigid points is statically indeterminate (the solver would
  /// share the load at random and the wheels with little of it would slip); sprung, each wheel
  /// carries its share.
  double tyre_deflection_per_radius = 0.015;
  /// Damping ratio of each wheel's contact spring (1: critical).
  double tyre_damping_ratio = 1.0;
  /// Mass of each steering knuckle (the hub a front wheel turns on), as a fraction of
  /// PhysicsDef::wheel_mass_kg.
  double knuckle_mass_fraction = 0.5;
  /// The steering servo's position gain: the share of a front wheel's angle error it removes
  /// in one step, on top of following the set-point's rate (Bullet's joint motor kp, erp 1).
  double steer_position_gain = 0.5;
  /// A car's constraint solver runs at least this many iterations a step (at most: it stops
  /// once converged; PhysicsDef::solver_iterations if more). Its 1.5 t chassis on 20 kg wheels
  /// converges slowly: at 15 the hand-made plan of CarEpisodeTest was tracked to 20 mm, at 50 to
  /// 4 mm (docs/simulation.md).
  int min_solver_iterations = 50;
  /// Largest torque of each front wheel's steering motor, N m; 0: PhysicsDef::max_wheel_torque_nm.
  double max_steer_torque_nm = 0.0;
};

}  // namespace parksim
