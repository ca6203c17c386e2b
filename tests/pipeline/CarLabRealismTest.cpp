// The realism presets with a car (issue 38): the presets' motors are the study robot's micro
// gear-motors (0.098 N m), which cannot move a 1800 kg car; a car's preset motors are sized
// from its mass, wheel radius and limits (realism/DriveSizing.h). The required torque is
// computed here from the world's own numbers, m a r / driven wheels. That the car then parks
// in 19 of 20 noise seeds is CarLabRealismRateTest.cpp.

#include <memory>
#include <string>

#include <gtest/gtest.h>

#include "parksim/pipeline/EpisodePipeline.h"
#include "parksim/pipeline/EpisodeSettings.h"
#include "parksim/realism/RealismDef.h"
#include "parksim/scenario/world/World.h"
#include "tests/support/TestPaths.h"

namespace parksim {
namespace {

EpisodeRequest request(const std::string& world, const std::string& realism) {
  EpisodeRequest r;
  r.world =
      std::make_shared<const World>(loadWorld(testing::sourceDir() + "/worlds/" + world + ".yaml"));
  r.realism = realism;
  return r;
}

// What each driven (rear) wheel must give to accelerate the whole car at its limit: the
// chassis and four wheels (the world's physics), the car's acceleration and wheel radius, two
// driven wheels.
double requiredTorque(const Scenario& s) {
  const double mass = s.physics.chassis_mass_kg + 4.0 * s.physics.wheel_mass_kg;
  return mass * s.robot.max_accel_mps2 * s.robot.wheel_radius_m / 2.0;
}

TEST(CarLabRealism, ThePresetsMotorsGiveTheCarsAccelerationUpToItsTopSpeed) {
  for (const char* preset : {"lab", "odometry"}) {
    const EpisodeRequest r = request("car_bay_forward", preset);
    const Scenario& s = r.world->scenario;
    const double needed = requiredTorque(s);
    ASSERT_NEAR(needed, 1800.0 * 1.0 * 0.33 / 2.0, 1e-9);  // the world file's numbers
    const MotorDef motor = resolveSettings(r).execution.realism.motor;
    ASSERT_TRUE(motor.enabled);
    // The torque-speed line at the car's top speed, less the drive train's start-up friction
    // and the rolling resistance (MotorModel.h), still gives the acceleration's torque.
    const double top_wheel_speed = s.robot.max_speed_mps / s.robot.wheel_radius_m;
    const double at_top_speed =
        motor.stall_torque_nm * (1.0 - top_wheel_speed / motor.no_load_speed_radps);
    const double friction =
        motor.startup_effort * motor.stall_torque_nm +
        motor.rolling_resistance * 0.5 * 1800.0 * s.physics.gravity_mps2 * s.robot.wheel_radius_m;
    EXPECT_GT(at_top_speed - friction, needed) << preset;
    EXPECT_GT(presetRealism(preset).motor.stall_torque_nm, 0.0);
    EXPECT_LT(presetRealism(preset).motor.stall_torque_nm, needed / 1000.0)
        << "the study's motor, for contrast";
  }
}

TEST(CarLabRealism, AStudyRobotKeepsThePresetExactly) {
  for (const char* preset : {"lab", "odometry"}) {
    const RealismDef resolved = resolveSettings(request("head_in", preset)).execution.realism;
    const RealismDef plain = presetRealism(preset);
    EXPECT_EQ(resolved.motor.stall_torque_nm, plain.motor.stall_torque_nm);
    EXPECT_EQ(resolved.motor.no_load_speed_radps, plain.motor.no_load_speed_radps);
    EXPECT_EQ(resolved.wheel_loop.kp, plain.wheel_loop.kp);
    EXPECT_EQ(resolved.wheel_loop.ki, plain.wheel_loop.ki);
  }
}

}  // namespace
}  // namespace parksim
