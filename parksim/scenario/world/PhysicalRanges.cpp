#include "parksim/scenario/world/PhysicalRanges.h"

#include <charconv>
#include <cmath>

#include "parksim/core/io/Error.h"
#include "parksim/core/io/NumberFormat.h"
#include "parksim/sim/world/CarModelDef.h"

namespace parksim {
namespace {

// Up to 3 significant digits, for forces and accelerations in messages.
std::string brief(double v) { return formatGeneral(v, 3); }

// Shortest round-trip text, for limits; in fixed notation from 1e-4 on ("0.0001", "100000"),
// as docs/limits.md writes them.
std::string exact(double v) {
  char buf[64];
  const auto [end, ec] = std::abs(v) >= 1e-4 && std::abs(v) < 1e15
                             ? std::to_chars(buf, buf + sizeof buf, v, std::chars_format::fixed)
                             : std::to_chars(buf, buf + sizeof buf, v);
  return ec == std::errc() ? std::string(buf, end) : std::string("?");
}

// Bullet caps a contact's combined friction at 10 (btManifoldResult, MAX_FRICTION): a larger
// coefficient would be a number the simulation does not use.
constexpr std::string_view kFrictionReason =
    "Bullet caps a contact's combined friction at 10; real tyres reach about 1.5";

}  // namespace

const std::vector<ParameterRange>& physicalRanges() {
  static const std::vector<ParameterRange> ranges = {
      {"robot.length", 0.005, 20.0, " m",
       "from a 5 mm micro robot, still several times the planner's 1 mm motion checks, to a "
       "20 m vehicle"},
      {"robot.width", 0.005, 20.0, " m",
       "from a 5 mm micro robot, still several times the planner's 1 mm motion checks, to a "
       "20 m vehicle"},
      {"robot.wheel_base", 0.005, 20.0, " m",
       "a track from a micro robot's 5 mm to a 20 m vehicle's"},
      {"robot.wheel_radius", 0.001, 5.0, " m",
       "from a 1 mm micro wheel to beyond the largest tyres (about 2 m)"},
      {"robot.max_wheel_speed_radps", 0.1, 1000.0, " rad/s",
       "a wheel's top speed: below 0.1 rad/s it turns less than 0.6 degrees per 0.1 s control "
       "period; 1000 rad/s is about 9500 rpm at the wheel, above any geared drive"},
      {"robot.max_wheel_accel_radps2", 0.1, 10000.0, " rad/s^2",
       "below 0.1 rad/s^2 a wheel takes minutes to reach a walking pace; above 10000 rad/s^2 it "
       "reaches 1000 rad/s in a tenth of a second"},
      {"robot.height", 0.002, 20.0, " m", "a body from 2 mm to 20 m tall"},
      // A car's own (robot.drive: car, docs/cars.md).
      {"robot.track", 0.005, 20.0, " m", "a track from a micro robot's 5 mm to a 20 m vehicle's"},
      {"robot.axle_distance", 0.005, 20.0, " m",
       "between the axles, from a micro robot's 5 mm to a 20 m vehicle's"},
      {"robot.max_steer_deg", 0.5, 80.0, " degrees",
       "below 0.5 degrees the tightest turn is over 100 wheelbases wide; cars steer their front "
       "wheels to about 40 degrees, and near 90 the bicycle model turns about its rear axle"},
      {"robot.max_steer_rate_degps", 0.1, 3600.0, " degrees/s",
       "from minutes from lock to lock to ten turns a second; cars steer their front wheels at "
       "about 30 degrees/s"},
      {"robot.max_speed_mps", 0.01, 100.0, " m/s",
       "from 1 cm/s, 1 mm per 0.1 s control period, to 360 km/h"},
      {"robot.max_accel_mps2", 0.01, 100.0, " m/s^2",
       "from a thousandth of g to 10 g, beyond any tyre's grip"},
      {"physics.time_step_s", 1e-5, 0.01, " s",
       "each 0.1 s control period of a plan is followed over at least 10 physics steps, and the "
       "realism's 100 Hz pose sensor takes one sample per step at most; below 10 us the limit "
       "of 1e6 steps leaves 10 s of simulated time"},
      {"physics.solver_iterations", 1.0, 1000.0, "",
       "Bullet's default is 10 and parksim's 50; beyond 1000 a step only costs more"},
      {"physics.gravity_mps2", 0.1, 100.0, " m/s^2",
       "from a small moon (Ceres: 0.28) to beyond Jupiter (24.8); without weight the wheels have "
       "no grip"},
      {"physics.chassis_mass_kg", 1e-3, 1e5, " kg", "from a 1 g micro robot to a 100 t vehicle"},
      {"physics.wheel_mass_kg", 1e-4, 1e4, " kg", "from a 0.1 g micro wheel to a 10 t one"},
      {"physics.wheel_friction", 0.0, 10.0, "", kFrictionReason},
      {"physics.support_friction", 0.0, 10.0, "", kFrictionReason},
      {"physics.ground_friction", 0.0, 10.0, "", kFrictionReason},
      {"physics.obstacle_friction", 0.0, 10.0, "", kFrictionReason},
      {"physics.max_wheel_torque_nm", 1e-6, 1e5, " N m",
       "from a micro motor's 1 uN m to a heavy vehicle's 100 kN m per wheel"},
      {"physics.parked_robot_mass_kg", 1e-3, 1e5, " kg",
       "from a 1 g micro robot to a 100 t vehicle"},
      {"parked_robots.mass_kg", 1e-3, 1e5, " kg", "from a 1 g micro robot to a 100 t vehicle"},
  };
  return ranges;
}

const ParameterRange& physicalRange(std::string_view key) {
  for (const ParameterRange& r : physicalRanges()) {
    if (r.key == key) return r;
  }
  throw Error("no physical range for " + std::string(key));
}

std::optional<std::string> rangeProblem(const ParameterRange& range, double value,
                                        std::string_view shown) {
  if (value >= range.lo && value <= range.hi) return std::nullopt;
  return "must be in [" + exact(range.lo) + ", " + exact(range.hi) + "]" + std::string(range.unit) +
         " (" + std::string(range.reason) + "), got " + std::string(shown) + " (docs/limits.md)";
}

WheelDemand wheelDemand(const RobotDef& r, const PhysicsDef& p) {
  const double mass = p.chassis_mass_kg + 2.0 * p.wheel_mass_kg;
  const double accel = r.wheel_radius_m * r.max_wheel_accel_radps2;  // m/s^2 at the axle
  // Chassis: a uniform box about its centre, moved to the axle's middle; wheels at +-b/2.
  const double d = r.footprintCenterOffset();
  const double half_base = 0.5 * r.wheel_base_m;
  const double yaw_inertia =
      p.chassis_mass_kg * ((r.length_m * r.length_m + r.width_m * r.width_m) / 12.0 + d * d) +
      2.0 * p.wheel_mass_kg * half_base * half_base;
  // Wheels accelerating in opposite directions at the limit turn the robot at 2 r alpha / b;
  // the torque I * that comes from two forces F on an arm of b/2 each: F = I * yaw_accel / b.
  const double yaw_accel = 2.0 * accel / r.wheel_base_m;
  WheelDemand w;
  w.straight_n = 0.5 * mass * accel;
  // A car never turns on the spot, and its steered front wheels' grip turns it, not a
  // difference between its driven wheels' forces.
  w.turn_n = r.isCar() ? 0.0 : yaw_inertia * yaw_accel / r.wheel_base_m;
  w.grip_n = p.wheel_friction * p.ground_friction * 0.5 * mass * p.gravity_mps2;
  return w;
}

std::optional<std::string> jointInertiaProblem(const RobotDef& r, const PhysicsDef& p) {
  const double radius = r.wheel_radius_m;
  const double wheel = 0.4 * p.wheel_mass_kg * radius * radius;
  const double knuckle_fraction = CarModelDef{}.knuckle_mass_fraction;
  // The knuckle: 2/5 (f m) (r/2)^2, below the wheel's own for any fraction under 4.
  const double knuckle = 0.4 * knuckle_fraction * p.wheel_mass_kg * 0.25 * radius * radius;
  const bool by_knuckle = r.isCar() && knuckle < wheel;
  const double least = by_knuckle ? knuckle : wheel;
  if (least >= kMinJointInertia_kgm2) return std::nullopt;
  const double per_kg = least / p.wheel_mass_kg;
  return std::string(by_knuckle ? "a steering knuckle's" : "a wheel's") +
         " inertia about its axis, " + brief(least) + " kg m^2 (physics.wheel_mass_kg " +
         brief(p.wheel_mass_kg) + " kg at robot.wheel_radius " + brief(radius) +
         " m), is below Bullet's " + brief(kMinJointInertia_kgm2) +
         " kg m^2, under which a joint never turns: at this radius a wheel needs " +
         brief(kMinJointInertia_kgm2 / per_kg) + " kg or more (docs/limits.md)";
}

std::optional<std::string> driveProblem(const RobotDef& r, const PhysicsDef& p) {
  if (std::optional<std::string> problem = jointInertiaProblem(r, p)) return problem;
  const WheelDemand w = wheelDemand(r, p);
  const double grip = kGripMargin * w.grip_n;
  const bool turning = w.turn_n > w.straight_n;
  const std::string what = turning ? "turning a " + brief(r.length_m) + " x " + brief(r.width_m) +
                                         " m body on a " + brief(r.wheel_base_m) + " m wheel base"
                                   : "accelerating the robot straight ahead";
  const std::string limit =
      " at the wheel acceleration limit (" + brief(r.max_wheel_accel_radps2) + " rad/s^2)";
  if (!(w.force_n() <= grip)) {
    // kGripMargin is why the limit is a multiple of the grip (PhysicalRanges.h).
    return what + limit + " needs " + brief(w.force_n()) + " N at each wheel, more than " +
           brief(kGripMargin) + " times their grip (" + brief(w.grip_n) +
           " N: wheel_friction x ground_friction x half the weight): " +
           (turning ? "widen robot.wheel_base, or lower robot.max_wheel_accel_radps2"
                    : "lower robot.max_wheel_accel_radps2") +
           " (docs/limits.md)";
  }
  const double torque = w.force_n() * r.wheel_radius_m;
  if (!(torque <= p.max_wheel_torque_nm)) {
    return what + limit + " needs " + brief(torque) + " N m at each wheel, more than " +
           "physics.max_wheel_torque_nm (" + brief(p.max_wheel_torque_nm) +
           "): raise it, or lower robot.max_wheel_accel_radps2 (docs/limits.md)";
  }
  return std::nullopt;
}

}  // namespace parksim
