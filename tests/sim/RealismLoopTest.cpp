// The realism loop's own behaviour: the robot as built per noise seed, the control ticks and
// the latency of set-points. Its physics (motors, slip, odometry) is RealismPhysicsTest's.

#include "parksim/sim/episode/RealismLoop.h"

#include <algorithm>

#include <gtest/gtest.h>

#include "tests/sim/SimTestSupport.h"

namespace parksim {
namespace {

TEST(RealismLoop, TheRobotAsBuiltIsDrawnPerNoiseSeedAndLayer) {
  const RobotBuild ideal = drawRobotBuild(presetRealism("ideal"), 7);
  EXPECT_EQ(ideal.left_scale, 1.0);
  EXPECT_EQ(ideal.track_scale, 1.0);
  EXPECT_EQ(ideal.left_gain, 1.0);

  RealismDef lab = presetRealism("lab");
  lab.calibration.radius_error_range_pct = 1.0;
  lab.calibration.track_error_range_pct = 1.0;
  const RobotBuild a = drawRobotBuild(lab, 7);
  const RobotBuild again = drawRobotBuild(lab, 7);
  const RobotBuild other = drawRobotBuild(lab, 8);
  EXPECT_EQ(a.left_scale, again.left_scale);
  EXPECT_EQ(a.right_gain, again.right_gain);
  EXPECT_NE(a.left_scale, other.left_scale);
  EXPECT_NEAR(a.left_scale, 1.0 + 0.01 * lab.calibration.left_radius_error_pct, 0.0100001);
  EXPECT_NEAR(a.track_scale, 1.0 + 0.01 * lab.calibration.track_error_pct, 0.0100001);
  // Switching the motors off leaves the calibration's draws as they were.
  RealismDef no_motor = lab;
  no_motor.motor.enabled = false;
  const RobotBuild b = drawRobotBuild(no_motor, 7);
  EXPECT_EQ(b.left_scale, a.left_scale);
  EXPECT_EQ(b.right_scale, a.right_scale);
  EXPECT_EQ(b.track_scale, a.track_scale);
  EXPECT_EQ(b.left_gain, 1.0);
}

TEST(RealismLoop, TheModelGetsTheRobotAsBuilt) {
  const Scenario s = testing::emptyLot();
  const RealismDef lab = presetRealism("lab");
  RobotBuild build;
  build.left_scale = 1.01;
  build.right_scale = 0.99;
  build.track_scale = 1.02;
  const SimModelDef ideal = withRobotBuild(SimModelDef{}, presetRealism("ideal"), build, s);
  EXPECT_EQ(ideal.body.left_radius_scale, 1.0);
  EXPECT_EQ(ideal.body.drive, WheelDrive::kVelocityMotor);
  const SimModelDef m = withRobotBuild(SimModelDef{}, lab, build, s);
  EXPECT_EQ(m.body.left_radius_scale, 1.01);
  EXPECT_EQ(m.body.right_radius_scale, 0.99);
  EXPECT_EQ(m.body.track_scale, 1.02);
  ASSERT_TRUE(lab.motor.enabled);
  EXPECT_EQ(m.body.drive, WheelDrive::kTorque);
  EXPECT_EQ(m.body.wheel_axle_inertia_kgm2, MotorModel(lab.motor, 1.0).axleInertia());
  EXPECT_GT(m.body.joint_friction_nm, MotorModel(lab.motor, 1.0).frictionTorque());
}

TEST(RealismLoop, SetPointsReachTheMotorsAfterTheLatencyAndAreHeld) {
  const Scenario s = testing::emptyLot();
  DynamicsWorld world(s, s.start);
  RealismDef r;
  r.name = "test";
  r.control.rate_hz = 50.0;
  r.control.latency_s = 5.0 / 240.0;  // 5 steps
  const double dt = world.timeStep();
  RealismLoop loop(r, 1, RobotBuild{}, s.robot, s.start, dt);
  EXPECT_EQ(loop.latency_steps, 5);
  EXPECT_DOUBLE_EQ(loop.holdPeriod(), 0.02);
  // Ticks at the first step at or after every multiple of 20 ms: steps 0, 5, 10, 15, 20, 24.
  // Each sends k + 1 rad/s, which the motors get 5 steps later and hold until the next.
  std::vector<long> ticks;
  double expected = 0.0;
  for (long k = 0; k <= 40; ++k) {
    if (loop.controlDue(k)) {
      ticks.push_back(k);
      loop.tick(k, {static_cast<double>(k) + 1.0, 0.0});
    }
    if (k >= 5 && std::find(ticks.begin(), ticks.end(), k - 5) != ticks.end()) {
      expected = static_cast<double>(k - 5) + 1.0;
    }
    loop.actuate(k, world);
    EXPECT_EQ(world.wheelTargets().left_radps, expected) << "step " << k;
  }
  EXPECT_EQ(std::vector<long>(ticks.begin(), ticks.begin() + 6),
            (std::vector<long>{0, 5, 10, 15, 20, 24}));
}

}  // namespace
}  // namespace parksim
