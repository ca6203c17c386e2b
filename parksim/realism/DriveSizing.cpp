#include "parksim/realism/DriveSizing.h"

namespace parksim {

namespace {

int wheelCount(const RobotDef& robot) { return robot.isCar() ? 4 : 2; }
int drivenWheels(const RobotDef& robot) { return robot.isCar() ? kCarDrivenWheels : 2; }

// How fast a driven wheel's speed answers its motor's effort, 1/s per unit effort: its stall
// torque over the wheel's share of the robot's inertia, m r^2 / driven wheels (the wheels'
// own inertia is small beside the robot's).
double effortAuthority(double stall_torque_nm, const RobotDef& robot, const PhysicsDef& physics) {
  const double mass = physics.chassis_mass_kg + wheelCount(robot) * physics.wheel_mass_kg;
  const double r = robot.wheel_radius_m;
  return stall_torque_nm / (mass * r * r / drivenWheels(robot));
}

}  // namespace

double accelerationTorque(const RobotDef& robot, const PhysicsDef& physics) {
  const double mass = physics.chassis_mass_kg + wheelCount(robot) * physics.wheel_mass_kg;
  const double accel =
      robot.isCar() ? robot.max_accel_mps2 : robot.wheel_radius_m * robot.max_wheel_accel_radps2;
  return mass * accel * robot.wheel_radius_m / drivenWheels(robot);
}

RealismDef sizedDrive(RealismDef realism, const RobotDef& robot, const PhysicsDef& physics) {
  if (!robot.isCar() || !realism.motor.enabled) return realism;
  MotorDef& motor = realism.motor;
  // The preset's loop, tuned on the study's robot with the preset's motor.
  const double study_authority = effortAuthority(motor.stall_torque_nm, RobotDef{}, PhysicsDef{});
  motor.stall_torque_nm = kCarStallTorqueMargin * accelerationTorque(robot, physics);
  motor.no_load_speed_radps = kCarNoLoadSpeedMargin * robot.max_wheel_speed_radps;
  const double gain = study_authority / effortAuthority(motor.stall_torque_nm, robot, physics);
  realism.wheel_loop.kp *= gain;
  realism.wheel_loop.ki *= gain;
  return realism;
}

RealismDef presetRealismFor(const std::string& name, const RobotDef& robot,
                            const PhysicsDef& physics) {
  return sizedDrive(presetRealism(name), robot, physics);
}

}  // namespace parksim
