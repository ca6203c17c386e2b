// The plan check's grip rule (planner/base/GripCheck.h): a plan whose accelerations or turns
// need more grip than the tyres have is refused before it is driven, naming the time, the
// force and the grip. Each prediction is computed here from mass, friction, g and the plan's own
// accelerations; a plan at 0.9 of it passes, one at 1.1 does not.

#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "parksim/core/model/DiffDrive.h"
#include "parksim/core/model/FootprintChecker.h"
#include "parksim/planner/base/PlanCheck.h"

namespace parksim {
// Named, not anonymous: its program is compiled as one unity batch, where another file's
// helpers of the same names would meet these.
namespace grip_check_test {

constexpr double kDt = 0.05;

class OpenLot : public FootprintChecker {
 public:
  bool isFree(const Pose2&, double) const override { return true; }
};

// A scenario whose limits let any plan below through: only the grip is under test.
Scenario openScenario(const RobotDef& robot) {
  Scenario s;
  s.robot = robot;
  s.robot.max_wheel_speed_radps = 1e6;
  s.robot.max_wheel_accel_radps2 = 1e9;
  s.robot.max_speed_mps = 1e3;
  s.robot.max_accel_mps2 = 1e6;
  s.robot.max_steer_rate_radps = 1e3;
  s.lot = {0.0, 0.0, 1000.0, 1000.0};
  s.start = {500.0, 500.0, 0.0};
  return s;
}

// Rows of wheel speeds (and a car's steering angle) each held kDt from the start, then a row at
// rest; the goal is where the plan ends.
Trajectory planOf(Scenario& s, const std::vector<std::pair<WheelSpeeds, double>>& rows) {
  Trajectory t;
  Pose2 pose = s.start;
  for (const auto& [w, steer] : rows) {
    t.points.push_back({t.points.size() * kDt, pose, w, steer});
    pose = integrateExact(pose, toTwist(w, s.robot), kDt);
  }
  t.points.push_back({t.points.size() * kDt, pose, {}, rows.back().second});
  s.goal.pose = pose;
  return t;
}

std::string reasonOf(const Scenario& s, const Trajectory& plan) {
  const OpenLot lot;
  const std::optional<PlanViolation> v = checkPlan(s, lot, plan);
  return v ? v->reason : std::string("(passes)");
}

// Regression (issue 39): a plan was checked against the motors' torque, not the tyres' grip.
// Straight ahead each wheel carries half the weight and gives half of mass x acceleration:
// the tyres slip above wheel_friction x ground_friction x g, whatever the mass.
TEST(GripCheck, AStraightStartFasterThanTheGripAllowsIsRefused) {
  Scenario s = openScenario(RobotDef{});
  s.physics.wheel_friction = 0.5;
  s.physics.ground_friction = 0.8;
  const double mu = 0.5 * 0.8;
  const double g = s.physics.gravity_mps2;
  const double mass = s.physics.chassis_mass_kg + 2.0 * s.physics.wheel_mass_kg;
  const double limit_mps2 = mu * g;
  const double r = s.robot.wheel_radius_m;
  for (const double share : {0.9, 1.1}) {
    // From rest to the speed that one step of the limit's acceleration reaches, held, then a
    // stop at the same rate.
    const double w = share * limit_mps2 * kDt / r;
    const Trajectory plan = planOf(s, {{{w, w}, 0.0}, {{w, w}, 0.0}});
    const std::string reason = reasonOf(s, plan);
    if (share < 1.0) {
      EXPECT_EQ(reason, "(passes)");
      continue;
    }
    const double demand = 0.5 * mass * share * limit_mps2;
    const double grip = mu * 0.5 * mass * g;
    char expected[256];
    std::snprintf(expected, sizeof expected,
                  "at t = 0.000 s (x 500.000 m, y 500.000 m, 0.0 deg) the right driven wheel "
                  "needs %.4g N of grip (%.4g N along, 0 N across), more than its %.4g N",
                  demand, demand, grip);
    EXPECT_EQ(reason.rfind(expected, 0), 0u) << reason << "\n" << expected;
    EXPECT_NE(reason.find("the tyres would slip"), std::string::npos) << reason;
  }
}

// Turning on the spot, the wheels push opposite ways: each gives yaw inertia x yaw
// acceleration / wheel base. A 1500 kg robot's 2 x 2 m body on a 0.5 m wheel base, on its
// wheels' grip alone.
TEST(GripCheck, AHeavyRobotSpinningFasterThanItsGripAllowsIsRefused) {
  RobotDef robot;
  robot.length_m = 2.0;
  robot.width_m = 2.0;
  robot.front_overhang_m = 1.0;  // the axle under the body's centre
  robot.wheel_base_m = 0.5;
  robot.wheel_radius_m = 0.2;
  Scenario s = openScenario(robot);
  s.physics.chassis_mass_kg = 1500.0;
  s.physics.wheel_mass_kg = 20.0;
  const double mass = 1540.0;
  // Chassis: a uniform 2 x 2 m box about its centre; wheels: point masses 0.25 m out.
  const double inertia = 1500.0 * (4.0 + 4.0) / 12.0 + 2.0 * 20.0 * 0.25 * 0.25;
  const double grip = 1.0 * 0.5 * mass * s.physics.gravity_mps2;
  // Wheel accelerations +-a turn the robot at 2a / b; each wheel then gives I (2a / b) / b.
  const double limit_mps2 = grip * 0.5 * 0.5 / (2.0 * inertia);
  for (const double share : {0.9, 1.1}) {
    const double w = share * limit_mps2 * kDt / robot.wheel_radius_m;
    const Trajectory plan = planOf(s, {{{-w, w}, 0.0}, {{-w, w}, 0.0}});
    const std::string reason = reasonOf(s, plan);
    if (share < 1.0) {
      EXPECT_EQ(reason, "(passes)");
    } else {
      EXPECT_NE(reason.find("driven wheel needs "), std::string::npos) << reason;
      EXPECT_EQ(reason.rfind("at t = 0.000 s", 0), 0u) << reason;
      char grip_text[64];
      std::snprintf(grip_text, sizeof grip_text, "more than its %.4g N", grip);
      EXPECT_NE(reason.find(grip_text), std::string::npos) << reason << "\n" << grip_text;
    }
  }
}

// A car's four wheels share its weight and the centripetal force: it slides out of a turn when
// speed^2 x curvature exceeds friction x g. The benchmarks' car on ice (friction 0.15) at
// 2.5 m/s; its two driven rear wheels, a quarter of the weight each, start it at 0.02 g.
TEST(GripCheck, ACarTurningFasterThanItsGripAllowsIsRefused) {
  Scenario s = openScenario(midSizeCar());
  s.physics.ground_friction = 0.15;
  const double mu = 0.15 * s.physics.wheel_friction;
  const double g = s.physics.gravity_mps2;
  const RobotDef& car = s.robot;
  const double v = 2.5;
  for (const double share : {0.9, 1.1}) {
    const double curvature = share * mu * g / (v * v);
    const double steer = std::atan(curvature * car.axle_distance_m);
    // Reaching 2.5 m/s from rest gently, so that the turn, not the start, is what is judged.
    const double gentle = 0.02 * g;
    std::vector<std::pair<WheelSpeeds, double>> rows;
    const int steps = static_cast<int>(std::ceil(v / (gentle * kDt)));
    for (int k = 1; k <= steps; ++k) {
      const double vk = std::min(v, k * gentle * kDt);
      rows.push_back({toWheelSpeeds({vk, 0.0}, car), 0.0});
    }
    for (int k = 0; k < 10; ++k) {  // steering at once (the rate is not limited here)
      rows.push_back({toWheelSpeeds({v, v * std::tan(steer) / car.axle_distance_m}, car), steer});
    }
    // And to rest, gently, straight.
    for (double vk = v; vk > 0.0; vk -= gentle * kDt) {
      rows.push_back({toWheelSpeeds({vk, 0.0}, car), 0.0});
    }
    const Trajectory plan = planOf(s, rows);
    const std::string reason = reasonOf(s, plan);
    if (share < 1.0) {
      EXPECT_EQ(reason, "(passes)");
    } else {
      const double mass = s.physics.chassis_mass_kg + 4.0 * s.physics.wheel_mass_kg;
      char across[64];
      std::snprintf(across, sizeof across, "%.4g N across), more than its %.4g N",
                    mass * v * v * curvature / 4.0, mu * mass * g / 4.0);
      EXPECT_NE(reason.find(across), std::string::npos) << reason << "\n" << across;
    }
  }
}

}  // namespace grip_check_test
}  // namespace parksim
