// Where the simulated robot rests besides its wheels (sim/world/RobotSupports.h): the study's robot
// keeps its one rigid rear slider exactly; a robot whose axle lies behind its middle (which, on
// the rear slider alone, pitches over) gets a rigid front one, and the car-sized robot with its
// axle under its middle sprung sliders at both ends; both stay upright under full torque.

#include "parksim/sim/world/RobotSupports.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "parksim/core/geometry/Angle.h"
#include "parksim/sim/world/DynamicsWorld.h"
#include "tests/sim/SimTestSupport.h"

namespace parksim {
namespace {

// The 4.25 x 2.43 m car of worlds/car_lot.yaml.
Scenario carScenario() {
  Scenario s = testing::emptyLot({10.0, 10.0, 0.0});
  s.lot = {0.0, 0.0, 40.0, 20.0};
  s.robot.length_m = 4.25;
  s.robot.width_m = 2.43;
  s.robot.front_overhang_m = 2.125;
  s.robot.wheel_base_m = 2.2;
  s.robot.wheel_radius_m = 0.3;
  s.robot.max_wheel_speed_radps = 10.0;
  s.robot.max_wheel_accel_radps2 = 10.0;
  s.robot.height_m = 1.5;
  s.robot.ground_clearance_m = 0.15;
  s.physics.chassis_mass_kg = 1500.0;
  s.physics.wheel_mass_kg = 75.0;
  s.physics.max_wheel_torque_nm = 1500.0;
  return s;
}

// The study's robot with its axle 10 mm from its rear edge instead of its front.
Scenario axleBehindTheMiddle() {
  Scenario s = testing::emptyLot({0.5, 1.0, 0.0});
  s.robot.front_overhang_m = 0.070;
  return s;
}

TEST(RobotSupports, TheStudyRobotKeepsItsOneRigidRearSlider) {
  const Scenario s;
  const RobotSupports r = robotSupports(s.robot, s.physics, SimModelDef{});
  EXPECT_TRUE(r.rear);
  EXPECT_FALSE(r.front);
  EXPECT_EQ(r.radius_m, SimModelDef{}.support_radius_m);
  // 10 mm forward of the rear edge, which lies 70 mm behind the axle.
  EXPECT_DOUBLE_EQ(r.rear_x_m, -0.060);
  EXPECT_EQ(r.stiffness_npm, 0.0);
  // Its centre of mass lies farther behind the axle than mu h: the rear slider alone holds it.
  EXPECT_GT(std::abs(r.com_ahead_m), r.friction * r.com_height_m);
}

// Its centre of mass 25.3 mm ahead of its axle, more than mu h = 24.9 mm: a rigid slider at the
// front holds it, as the rear one holds the study's robot.
TEST(RobotSupports, AnAxleBehindTheMiddleGetsOneRigidFrontSlider) {
  const Scenario s = axleBehindTheMiddle();
  const RobotSupports r = robotSupports(s.robot, s.physics, SimModelDef{});
  EXPECT_FALSE(r.rear);
  EXPECT_TRUE(r.front);
  EXPECT_DOUBLE_EQ(r.front_x_m, 0.060);  // 10 mm behind the front edge, 70 mm ahead of the axle
  EXPECT_EQ(r.stiffness_npm, 0.0);
  EXPECT_GT(r.com_ahead_m, r.friction * r.com_height_m);
}

// The car's axle lies under its middle: its centre of mass too, and no one slider holds it.
TEST(RobotSupports, AnAxleUnderTheMiddleGetsSprungSlidersAtBothEnds) {
  const Scenario s = carScenario();
  const RobotSupports r = robotSupports(s.robot, s.physics, SimModelDef{});
  EXPECT_TRUE(r.rear && r.front);
  EXPECT_LE(std::abs(r.com_ahead_m), r.friction * r.com_height_m);
  // Sized in proportion to the robot: inset and radius the study's times its size.
  const double scale = s.robot.sizeScale();
  EXPECT_NEAR(r.front_x_m, s.robot.front_overhang_m - 0.010 * scale, 1e-12);
  EXPECT_NEAR(r.rear_x_m, s.robot.front_overhang_m - s.robot.length_m + 0.010 * scale, 1e-12);
  EXPECT_NEAR(r.radius_m, 0.008 * scale, 1e-12);
  // The robot's whole weight compresses one slider by the deflection (0.2 mm x scale).
  const double m =
      s.physics.chassis_mass_kg + 2.0 * s.physics.wheel_mass_kg + SimModelDef{}.support_mass_kg;
  EXPECT_NEAR(m * s.physics.gravity_mps2 / r.stiffness_npm, 0.0002 * scale, 1e-12);
}

// Largest tilt while the wheels are driven from rest to full speed forward, then straight to
// full speed backward (the motors push at their torque limit, the wheels at their grip), then
// held there.
double maxTiltDrivingHard(const Scenario& s) {
  DynamicsWorld world(s, s.start);
  const double w = s.robot.max_wheel_speed_radps;
  double tilt = 0.0;
  const int steps = static_cast<int>(std::lround(1.0 / s.physics.time_step_s));
  for (int i = 0; i < 3 * steps; ++i) {
    const double target = i < steps ? w : -w;
    world.setWheelTargets({target, target});
    world.step();
    tilt = std::max(tilt, world.robot().tilt_rad);
  }
  return tilt;
}

// Upright: the rigid slider stops the pitch at once; sprung ones carry at most the robot's
// weight each, so each yields at most the deflection d and the body tilts by at most about
// 2 d over the distance between them (0.4 mm over 3.9 m for the car, 0.01 deg) plus the
// wheels' and sliders' contact softness. Under 1 degree is upright; on the rear slider alone
// (before issue 30) the robot whose axle lies behind its middle pitches onto its nose as it
// starts and ends its plan 0.67 m from its goal.
TEST(RobotSupports, ARobotWithItsAxleBehindTheMiddleAndTheCarStayUpright) {
  for (const Scenario& s : {axleBehindTheMiddle(), carScenario()}) {
    const double tilt = maxTiltDrivingHard(s);
    std::printf("robot %.3f m: max tilt %.4f deg\n", s.robot.length_m, radToDeg(tilt));
    EXPECT_LT(radToDeg(tilt), 1.0) << s.robot.length_m;
  }
}

}  // namespace
}  // namespace parksim
