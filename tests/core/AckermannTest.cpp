// A car's steering geometry (core/model/Ackermann.h) against the turn's centre, found here.

#include "parksim/core/model/Ackermann.h"

#include <cmath>

#include <gtest/gtest.h>

namespace parksim {
namespace {

TEST(AckermannTest, BothFrontWheelsPointAtTheTurnsCentre) {
  const RobotDef car = midSizeCar();
  const double l = car.axle_distance_m;
  const double half_track = 0.5 * car.wheel_base_m;
  for (const double steer : {0.75, 0.3, 0.01, -0.2, -0.75}) {
    const FrontWheelAngles w = ackermannAngles(car, steer);
    // The centre lies on the rear axle's line, R = L / tan(steer) to the left of the
    // reference point. A wheel at (L, y) points at it when its heading is perpendicular to the
    // line from the wheel to the centre: tan(angle) = L / (R - y).
    const double r = l / std::tan(steer);
    EXPECT_NEAR(std::tan(w.left_rad), l / (r - half_track), 1e-12) << steer;
    EXPECT_NEAR(std::tan(w.right_rad), l / (r + half_track), 1e-12) << steer;
    // The inner wheel turns more; both to the bicycle angle's side.
    EXPECT_GT(std::abs(steer > 0 ? w.left_rad : w.right_rad),
              std::abs(steer > 0 ? w.right_rad : w.left_rad));
    EXPECT_GT(w.left_rad * steer, 0.0);
    EXPECT_GT(w.right_rad * steer, 0.0);
    EXPECT_NEAR(bicycleAngle(car, w), steer, 1e-12) << steer;
  }
  const FrontWheelAngles straight = ackermannAngles(car, 0.0);
  EXPECT_EQ(straight.left_rad, 0.0);
  EXPECT_EQ(straight.right_rad, 0.0);
}

TEST(AckermannTest, RearWheelsRollOnTheBicycleModelsCircle) {
  const RobotDef car = midSizeCar();
  const double steer = 0.5;
  const double v = 2.0;
  const WheelSpeeds w = carWheelSpeeds(car, v, steer);
  // Each rear wheel's rim speed is the reference speed scaled by its own radius of the turn.
  const double r = car.axle_distance_m / std::tan(steer);
  EXPECT_NEAR(w.left_radps * car.wheel_radius_m, v * (r - 0.5 * car.wheel_base_m) / r, 1e-12);
  EXPECT_NEAR(w.right_radps * car.wheel_radius_m, v * (r + 0.5 * car.wheel_base_m) / r, 1e-12);
  EXPECT_NEAR(steerCurvature(car, steer), 1.0 / r, 1e-12);
  EXPECT_NEAR(curvatureSteer(car, 1.0 / r), steer, 1e-12);
  // The fastest rear wheel at top speed and full lock is the car's wheel-speed limit.
  const WheelSpeeds fastest = carWheelSpeeds(car, car.max_speed_mps, car.max_steer_rad);
  EXPECT_NEAR(fastest.right_radps, car.max_wheel_speed_radps, 1e-9);
}

}  // namespace
}  // namespace parksim
