#include "parksim/planner/base/GripCheck.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "parksim/core/geometry/Angle.h"
#include "parksim/core/io/NumberFormat.h"
#include "parksim/core/model/DiffDrive.h"

namespace parksim {

namespace {

std::string newtons(double v) { return formatGeneral(v, 4); }

}  // namespace

GripModel gripModel(const Scenario& s) {
  const RobotDef& r = s.robot;
  const PhysicsDef& p = s.physics;
  GripModel g;
  g.wheels_bearing = r.isCar() ? 4 : 2;
  g.mass_kg = p.chassis_mass_kg + g.wheels_bearing * p.wheel_mass_kg;
  const double d = r.footprintCenterOffset();
  const double half_base = 0.5 * r.wheel_base_m;
  g.yaw_inertia =
      p.chassis_mass_kg * ((r.length_m * r.length_m + r.width_m * r.width_m) / 12.0 + d * d) +
      2.0 * p.wheel_mass_kg * half_base * half_base;
  g.grip_n = p.wheel_friction * p.ground_friction * g.mass_kg * p.gravity_mps2 / g.wheels_bearing;
  return g;
}

std::optional<PlanViolation> gripViolation(const Scenario& s, const Trajectory& plan) {
  const std::vector<TrajectoryPoint>& pts = plan.points;
  if (pts.size() < 2) return std::nullopt;
  const RobotDef& robot = s.robot;
  const GripModel g = gripModel(s);
  const double r = robot.wheel_radius_m;
  const double b = robot.wheel_base_m;
  WheelSpeeds before{};  // at rest at the start
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const TrajectoryPoint& p = pts[i];
    const bool last = i + 1 == pts.size();
    const WheelSpeeds w = last ? WheelSpeeds{} : p.wheels;  // the plan ends at rest
    const double period = last ? p.t_s - pts[i - 1].t_s : pts[i + 1].t_s - p.t_s;
    const double al = r * (w.left_radps - before.left_radps) / period;  // m/s^2 at the wheel
    const double ar = r * (w.right_radps - before.right_radps) / period;
    const double accel = 0.5 * (al + ar);
    const double yaw_accel = (ar - al) / b;
    const double turn_n = robot.isCar() ? 0.0 : g.yaw_inertia * yaw_accel / b;
    // The centripetal force at the faster of the speeds on either side of the step.
    const Twist held = toTwist(w, robot);
    const Twist prior = toTwist(before, robot);
    const double centripetal = std::max(std::abs(held.v_mps * held.omega_radps),
                                        std::abs(prior.v_mps * prior.omega_radps));
    const double lateral_n = g.mass_kg * centripetal / g.wheels_bearing;
    const double left_n = 0.5 * g.mass_kg * accel - turn_n;
    const double right_n = 0.5 * g.mass_kg * accel + turn_n;
    const bool right = std::abs(right_n) >= std::abs(left_n);
    const double longitudinal_n = right ? right_n : left_n;
    const double demand_n = std::hypot(longitudinal_n, lateral_n);
    if (demand_n > g.grip_n * (1.0 + 1e-9) + 1e-12) {
      const std::string reason =
          "at t = " + formatFixed(p.t_s, 3) + " s (x " + formatFixed(p.pose.x, 3) + " m, y " +
          formatFixed(p.pose.y, 3) + " m, " + formatFixed(radToDeg(p.pose.theta), 1) +
          " deg) the " + (right ? "right" : "left") + " driven wheel needs " + newtons(demand_n) +
          " N of grip (" + newtons(std::abs(longitudinal_n)) + " N along, " + newtons(lateral_n) +
          " N across), more than its " + newtons(g.grip_n) +
          " N (physics.wheel_friction x ground_friction x its share of the weight): the "
          "tyres would slip; plan gentler accelerations and turns (robot.max_wheel_accel_radps2" +
          std::string(robot.isCar() ? ", max_accel_mps2, max_speed_mps" : "") + ")";
      return PlanViolation{p.t_s, p.pose, reason};
    }
    before = w;
  }
  return std::nullopt;
}

}  // namespace parksim
