#pragma once
// A car's scenarios and hand-made plans for the simulation tests: the mid-size car
// (RobotDef.h's midSizeCar) on an empty lot with a car's physics, and plans built from phases of
// speed and steering ramped within the car's limits.

#include <algorithm>
#include <cmath>
#include <vector>

#include "parksim/core/model/Ackermann.h"
#include "parksim/core/model/DiffDrive.h"
#include "parksim/core/model/Scenario.h"
#include "parksim/core/model/Trajectory.h"

namespace parksim::testing {

/// A car's masses and torques: 1.5 t chassis, 20 kg wheels, 1 kN m a rear wheel (3.8 m/s^2 on
/// the level, below the rear tyres' grip at friction 1).
inline PhysicsDef carPhysics() {
  PhysicsDef p;
  p.chassis_mass_kg = 1500.0;
  p.wheel_mass_kg = 20.0;
  p.max_wheel_torque_nm = 1000.0;
  p.parked_robot_mass_kg = 1500.0;
  return p;
}

/// An empty 100 x 100 m lot with the mid-size car at `start`.
inline Scenario carLot(const Pose2& start = {50.0, 50.0, 0.0}) {
  Scenario s;
  s.name = "car_lot";
  s.robot = midSizeCar();
  s.physics = carPhysics();
  s.lot = {0.0, 0.0, 100.0, 100.0};
  s.start = start;
  s.goal.pose = start;
  s.goal.position_tolerance_m = 0.1;
  s.goal.heading_tolerance_rad = 0.01;
  return s;
}

/// A phase of a car plan: speed and steering move toward these at the car's acceleration and
/// steering rate (both at once, one step per period), then hold them for `hold_s`.
struct CarPhase {
  double speed_mps = 0.0;
  double steer_rad = 0.0;
  double hold_s = 0.0;
};

/// The plan of `phases` from `start`, in periods of `period_s`: each point holds a speed and a
/// steering angle (its rear wheels' speeds, carWheelSpeeds) for one period, integrated exactly;
/// ends with a point at rest. Speed crosses zero only through a point at rest (gear changes
/// stop).
inline Trajectory carPlan(const Pose2& start, const std::vector<CarPhase>& phases,
                          const RobotDef& car, double period_s = 0.05) {
  Trajectory plan;
  Pose2 pose = start;
  double v = 0.0;
  double steer = 0.0;
  auto push = [&] {
    const double t = static_cast<double>(plan.points.size()) * period_s;
    plan.points.push_back({t, pose, carWheelSpeeds(car, v, steer), steer});
    pose = integrateExact(pose, {v, v * steerCurvature(car, steer)}, period_s);
  };
  const double dv = car.max_accel_mps2 * period_s;
  const double dsteer = car.max_steer_rate_radps * period_s;
  for (const CarPhase& phase : phases) {
    while (v != phase.speed_mps || steer != phase.steer_rad) {
      double next = v + std::clamp(phase.speed_mps - v, -dv, dv);
      if ((v > 0.0 && next < 0.0) || (v < 0.0 && next > 0.0)) next = 0.0;
      v = next;
      steer += std::clamp(phase.steer_rad - steer, -dsteer, dsteer);
      push();
    }
    const long hold = std::lround(phase.hold_s / period_s);
    for (long i = 0; i < hold; ++i) push();
  }
  const double t = static_cast<double>(plan.points.size()) * period_s;
  plan.points.push_back({t, pose, WheelSpeeds{}, steer});
  return plan;
}

}  // namespace parksim::testing
