// The simulated robot against ideal unicycle kinematics, and at rest.

#include "sim/DynamicsWorld.h"

#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "core/Angle.h"
#include "core/DiffDrive.h"
#include "tests/sim/SimTestSupport.h"

namespace parksim {
namespace {

struct StepResponse {
  double max_pos_err_m = 0.0;
  double final_pos_err_m = 0.0;
  double final_heading_err_rad = 0.0;
  Twist final_twist;
};

// Holds `wheels` from rest for `duration_s` and compares with the unicycle driven by the same
// wheel speeds from t = 0.
StepResponse stepResponse(const WheelSpeeds& wheels, double duration_s) {
  const Scenario s = testing::emptyLot({0.5, 0.5, 0.3});
  DynamicsWorld world(s, s.start);
  world.setWheelTargets(wheels);
  const long steps = std::lround(duration_s / world.timeStep());
  StepResponse out;
  const Twist twist = toTwist(wheels, s.robot);
  for (long k = 1; k <= steps; ++k) {
    world.step();
    const Pose2 ideal = integrateExact(s.start, twist, world.time());
    const RobotState state = world.robot();
    out.max_pos_err_m = std::max(out.max_pos_err_m, positionDistance(state.pose, ideal));
    out.final_pos_err_m = positionDistance(state.pose, ideal);
    out.final_heading_err_rad = angleDiff(state.pose.theta, ideal.theta);
    out.final_twist = state.twist;
  }
  std::printf(
      "step response %.2f/%.2f rad/s for %.1f s: max %.3f mm, final %.3f mm, %.3f deg, "
      "v %.6f (ideal %.6f) omega %.6f (ideal %.6f)\n",
      wheels.left_radps, wheels.right_radps, duration_s, out.max_pos_err_m * 1e3,
      out.final_pos_err_m * 1e3, radToDeg(out.final_heading_err_rad), out.final_twist.v_mps,
      twist.v_mps, out.final_twist.omega_radps, twist.omega_radps);
  return out;
}

TEST(DynamicsWorld, StartsAtTheRequestedPoseWithTheFootprintPlaced) {
  const Scenario s = testing::emptyLot({0.3, 0.7, degToRad(40)});
  DynamicsWorld world(s, s.start);
  const RobotState state = world.robot();
  EXPECT_NEAR(state.pose.x, 0.3, 1e-6);
  EXPECT_NEAR(state.pose.y, 0.7, 1e-6);
  EXPECT_NEAR(state.pose.theta, degToRad(40), 1e-6);
  EXPECT_NEAR(state.axle_height_m, s.robot.wheel_radius_m, 1e-6);
}

TEST(DynamicsWorld, StraightStepResponseFollowsTheUnicycle) {
  const StepResponse r = stepResponse({5.0, 5.0}, 5.0);
  EXPECT_LT(r.max_pos_err_m, 0.002);
}

TEST(DynamicsWorld, ArcStepResponseFollowsTheUnicycle) {
  const StepResponse r = stepResponse({3.0, 6.0}, 5.0);
  EXPECT_LT(r.max_pos_err_m, 0.002);
}

TEST(DynamicsWorld, TurnInPlaceStepResponseFollowsTheUnicycle) {
  const StepResponse r = stepResponse({-4.0, 4.0}, 5.0);
  EXPECT_LT(r.max_pos_err_m, 0.002);
}

TEST(DynamicsWorld, RestsWithoutSinkingBouncingOrSleeping) {
  const Scenario s = testing::emptyLot();
  DynamicsWorld world(s, s.start);
  const long steps = std::lround(10.0 / world.timeStep());
  double min_z = 1.0, max_z = 0.0, max_drift = 0.0, max_tilt = 0.0;
  for (long k = 0; k < steps; ++k) {
    world.step();
    const RobotState state = world.robot();
    min_z = std::min(min_z, state.axle_height_m);
    max_z = std::max(max_z, state.axle_height_m);
    max_drift = std::max(max_drift, positionDistance(state.pose, s.start));
    max_tilt = std::max(max_tilt, state.tilt_rad);
    ASSERT_TRUE(state.awake) << "asleep at step " << k;
  }
  std::printf("rest: axle z %.6f..%.6f mm, drift %.6f mm, tilt %.4f deg\n", min_z * 1e3,
              max_z * 1e3, max_drift * 1e3, radToDeg(max_tilt));
}

}  // namespace
}  // namespace parksim
