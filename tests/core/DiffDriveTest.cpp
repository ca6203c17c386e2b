#include "parksim/core/model/DiffDrive.h"

#include <cmath>
#include <random>

#include <gtest/gtest.h>

namespace parksim {
namespace {

TEST(DiffDrive, WheelMapsAreInverse) {
  const RobotDef robot;
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int i = 0; i < 1000; ++i) {
    const Twist tw{0.2 * u(rng), 3.0 * u(rng)};
    const Twist back = toTwist(toWheelSpeeds(tw, robot), robot);
    EXPECT_NEAR(back.v_mps, tw.v_mps, 1e-12);
    EXPECT_NEAR(back.omega_radps, tw.omega_radps, 1e-12);
  }
}

TEST(DiffDrive, WheelSpeedsOfKnownMotions) {
  const RobotDef robot;  // r = 20 mm, track 85 mm
  const WheelSpeeds straight = toWheelSpeeds({0.1, 0.0}, robot);
  EXPECT_DOUBLE_EQ(straight.left_radps, 5.0);
  EXPECT_DOUBLE_EQ(straight.right_radps, 5.0);
  // Turning in place counter-clockwise: right wheel forward, left backward, v_wheel = omega*w/2.
  const WheelSpeeds spin = toWheelSpeeds({0.0, 2.0}, robot);
  EXPECT_NEAR(spin.right_radps, 2.0 * 0.0425 / 0.02, 1e-12);
  EXPECT_NEAR(spin.left_radps, -2.0 * 0.0425 / 0.02, 1e-12);
}

TEST(DiffDrive, IntegrateExactMatchesFineEulerIntegration) {
  const Pose2 start{0.3, -0.2, 0.7};
  for (const Twist tw : {Twist{0.15, 0.0}, Twist{0.1, 1.3}, Twist{-0.08, -2.1}, Twist{0.0, 1.0}}) {
    const double dt = 0.1;
    const Pose2 exact = integrateExact(start, tw, dt);
    Pose2 euler = start;
    const int n = 200000;
    for (int i = 0; i < n; ++i) {
      const double h = dt / n;
      euler.x += tw.v_mps * std::cos(euler.theta + 0.5 * tw.omega_radps * h) * h;
      euler.y += tw.v_mps * std::sin(euler.theta + 0.5 * tw.omega_radps * h) * h;
      euler.theta += tw.omega_radps * h;
    }
    EXPECT_NEAR(exact.x, euler.x, 1e-9);
    EXPECT_NEAR(exact.y, euler.y, 1e-9);
    EXPECT_NEAR(exact.theta, wrapAngle(euler.theta), 1e-9);
  }
}

TEST(DiffDrive, FullCircleReturnsToStart) {
  const Pose2 start{1.0, 0.5, 0.3};
  Pose2 p = start;
  const Twist tw{0.1, 2.0 * kPi / 4.0};  // one turn in 4 s
  for (int i = 0; i < 40; ++i) p = integrateExact(p, tw, 0.1);
  EXPECT_NEAR(p.x, start.x, 1e-12);
  EXPECT_NEAR(p.y, start.y, 1e-12);
  EXPECT_NEAR(angleDiff(p.theta, start.theta), 0.0, 1e-12);
}

}  // namespace
}  // namespace parksim
