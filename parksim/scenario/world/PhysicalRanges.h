#pragma once
// The ranges a real robot and a stable simulation can have, checked when a world file is read
// (docs/limits.md, "Robot and physics"): every robot: and physics: value within a range that
// spans real robots from a 1 cm micro robot to a 10 m vehicle, each range with its reason; and
// two checks that join several values, because no single value is wrong in them: the wheels'
// grip and the motors' torque must be able to give the accelerations the robot's limits ask for.
// Values outside these ranges made episodes that planned exactly and then ended metres from
// their goal (a 1e-12 m wheel base, a 1e-300 kg chassis, a 1000 s time step).

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "parksim/core/model/Scenario.h"

namespace parksim {

/// A world-file value's accepted range and why.
struct ParameterRange {
  std::string_view key;  ///< as in the file, e.g. "robot.wheel_base"
  double lo = 0.0;       ///< smallest accepted value
  double hi = 0.0;       ///< largest accepted value
  std::string_view unit;
  std::string_view reason;  ///< one clause, for messages and docs/limits.md
};

/// Every range, robot: keys first, then physics: keys.
const std::vector<ParameterRange>& physicalRanges();

/// The range of `key` ("robot.wheel_base", "physics.time_step_s",
/// "parked_robots.mass_kg"). Throws Error for a key without one.
const ParameterRange& physicalRange(std::string_view key);

/// What is wrong with `value` for `range` ("must be in [0.005, 20] m (<reason>), got 1e-12"),
/// or nothing. `shown` is the value as written.
std::optional<std::string> rangeProblem(const ParameterRange& range, double value,
                                        std::string_view shown);

/// What the wheels must do at the robot's acceleration limit, in N per wheel: the grip force
/// to accelerate the whole robot straight ahead, and to start a turn on the spot (yaw inertia of
/// the chassis, a uniform box about the axle's middle, and of the wheels, as point masses; none
/// for a car, which never turns on the spot).
struct WheelDemand {
  double straight_n = 0.0;
  double turn_n = 0.0;
  /// The most the two wheels' grip can give each: (wheel_friction x ground_friction, Bullet's
  /// combined friction) x half the robot's weight (as if it all rested on the wheels).
  double grip_n = 0.0;
  double force_n() const { return straight_n > turn_n ? straight_n : turn_n; }
};

WheelDemand wheelDemand(const RobotDef& robot, const PhysicsDef& physics);

/// How far the demand at the acceleration limit may exceed the grip before a robot is refused.
/// The limit is asked for only in short bursts, which the tracking controller absorbs: on the
/// study's wheels (grip 1.18 N) a 0.6 m square body (demand 2.3 times the grip) still parked
/// within the 1 mm tolerance, a 0.7 m one (3.1 times) ended 1.6 mm off and a 1 m one (6.3 times)
/// 151 mm off (parksim 0.3.0, `run` on a 3 m lot, a 1 m x 1 m move with a quarter turn).
inline constexpr double kGripMargin = 2.5;

/// Bullet's least inertia about a joint's axis: btMultiBody gives a revolute joint below it
/// (SIMD_EPSILON, FLT_EPSILON in the single-precision Bullet parksim builds with) no
/// acceleration at all, so the wheel never turns (sim/world/RobotBody.cpp, which checks the
/// body as built again).
inline constexpr double kMinJointInertia_kgm2 = 1.1920928955078125e-07;

/// Why the simulation cannot turn the robot's wheels, or nothing: a wheel's inertia about its
/// axle (a solid sphere of physics.wheel_mass_kg and robot.wheel_radius, 2/5 m r^2), or a
/// car's steering knuckle's (sim/world/CarModelDef.h: a sphere of knuckle_mass_fraction of a
/// wheel's mass and half its radius), below kMinJointInertia_kgm2. Checked with the other
/// values when the world is read, so that a sweep refuses such a point before any episode runs.
std::optional<std::string> jointInertiaProblem(const RobotDef& robot, const PhysicsDef& physics);

/// Why the robot cannot follow plans made to its own limits, or nothing: the grip is smaller
/// than the force its acceleration limit needs by more than kGripMargin (a 5 x 5 m body
/// turning on an 85 mm wheel base), or max_wheel_torque_nm is smaller than that force at the
/// wheel's radius, or jointInertiaProblem.
std::optional<std::string> driveProblem(const RobotDef& robot, const PhysicsDef& physics);

}  // namespace parksim
