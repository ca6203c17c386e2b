#pragma once
// A realism preset's drive (motors and wheel-speed loop) sized to the robot it drives. The
// presets' motors are the study robot's (a 0.098 N m micro gear-motor, docs/realism.md): on a
// 1800 kg car they give a ten-thousandth of the torque its acceleration needs, and it does not
// move. A car gets motors sized from its own mass, wheel radius and limits instead, and a
// wheel-speed loop as quick on its wheels as the study's loop is on the study's.
//
// A differential drive keeps the preset's motors (the study's worlds byte for byte; a
// differential robot of another size sets its motors in the world's realism: section).

#include "parksim/core/model/RobotDef.h"
#include "parksim/core/model/Scenario.h"
#include "parksim/realism/RealismDef.h"

namespace parksim {

/// A car's stall torque over the torque its acceleration limit needs at each driven wheel
/// (m a r / driven wheels): what is left is for the speed's back-EMF, rolling resistance and
/// the drive train's start-up friction, and for feedback.
inline constexpr double kCarStallTorqueMargin = 4.0;
/// A car's motors' no-load speed over its largest wheel speed: at top speed half the stall
/// torque is left.
inline constexpr double kCarNoLoadSpeedMargin = 2.0;
/// A car's driven wheels: its rear wheels (CarBody.h).
inline constexpr int kCarDrivenWheels = 2;

/// The torque each driven wheel needs to accelerate the robot at its limit, N m: the mass of
/// the chassis and the four wheels (two for a differential drive) times the acceleration
/// (max_accel_mps2, a differential drive's wheel_radius x max_wheel_accel) times the wheel
/// radius, shared by the driven wheels.
double accelerationTorque(const RobotDef& robot, const PhysicsDef& physics);

/// `realism` with its drive sized to `robot` when it is a car and the motors are on (the
/// presets lab and odometry): stall torque kCarStallTorqueMargin x accelerationTorque,
/// no-load speed kCarNoLoadSpeedMargin x max_wheel_speed, the same unloaded time constant, and
/// the wheel-speed loop's gains scaled so that the loaded wheel answers an effort as fast as the
/// study robot's does (stall torque over the wheel's share of the robot's inertia, m r^2 /
/// driven wheels). Otherwise `realism` unchanged.
RealismDef sizedDrive(RealismDef realism, const RobotDef& robot, const PhysicsDef& physics);

/// presetRealism(name) with its drive sized to the robot (sizedDrive): what `--realism NAME`
/// and a world's `realism: {preset: NAME}` give a robot.
RealismDef presetRealismFor(const std::string& name, const RobotDef& robot,
                            const PhysicsDef& physics);

}  // namespace parksim
