#include "parksim/sim/world/RobotSupports.h"

#include <algorithm>
#include <cmath>

#include "parksim/sim/world/DynamicsWorld.h"

namespace parksim {

RobotSupports robotSupports(const RobotDef& robot, const PhysicsDef& physics,
                            const SimModelDef& model) {
  RobotSupports s;
  const double scale = robot.sizeScale();
  s.radius_m = model.support_radius_m * scale;
  const double inset = model.support_inset_m * scale;
  s.rear_x_m = robot.front_overhang_m - robot.length_m + inset;
  s.front_x_m = robot.front_overhang_m - inset;
  // Bullet combines friction coefficients by their product, capped at 10.
  s.friction = std::min(physics.wheel_friction * physics.ground_friction, 10.0);

  // The centre of mass with the slider at the chassis centre's end (the rear when the chassis
  // centre lies on the axle).
  const double chassis_x = robot.footprintCenterOffset();
  const double chassis_z = 0.5 * (robot.ground_clearance_m + robot.height_m);
  const bool ahead = chassis_x > 0.0;
  const double slider_x = ahead ? s.front_x_m : s.rear_x_m;
  const double m_chassis = physics.chassis_mass_kg;
  const double m_wheels = 2.0 * physics.wheel_mass_kg;
  const double m_slider = model.support_mass_kg;
  const double m = m_chassis + m_wheels + m_slider;
  s.com_ahead_m = (m_chassis * chassis_x + m_slider * slider_x) / m;
  s.com_height_m =
      (m_chassis * chassis_z + m_wheels * robot.wheel_radius_m + m_slider * s.radius_m) / m;

  const bool holds_alone = std::abs(s.com_ahead_m) > s.friction * s.com_height_m;
  s.rear = !ahead || !holds_alone;
  s.front = ahead || !holds_alone;
  if (!holds_alone) {
    // The robot's whole weight on one slider compresses it by the deflection; critical damping
    // of the robot's mass on that spring.
    const double deflection = model.support_deflection_m * scale;
    s.stiffness_npm = m * physics.gravity_mps2 / deflection;
    s.damping_nspm = 2.0 * std::sqrt(s.stiffness_npm * m);
  }
  return s;
}

}  // namespace parksim
