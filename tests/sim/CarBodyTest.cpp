// The simulated car (sim/CarBody.h) against the bicycle model's predictions, computed here:
// circles of radius axle / tan(steer), the steering's rate limit, straight driving.

#include <cmath>
#include <cstdio>
#include <vector>

#include <gtest/gtest.h>
#include <Eigen/Dense>

#include "parksim/core/geometry/Angle.h"
#include "parksim/core/model/Ackermann.h"
#include "parksim/sim/world/DynamicsWorld.h"
#include "tests/sim/CarTestSupport.h"

namespace parksim {
namespace {

// The circle through `points` in the least-squares sense of x^2 + y^2 + D x + E y + F = 0
// (Kasa's fit): its radius, m.
double fittedRadius(const std::vector<Eigen::Vector2d>& points) {
  Eigen::MatrixXd a(points.size(), 3);
  Eigen::VectorXd b(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    a(Eigen::Index(i), 0) = points[i].x();
    a(Eigen::Index(i), 1) = points[i].y();
    a(Eigen::Index(i), 2) = 1.0;
    b(Eigen::Index(i)) = -points[i].squaredNorm();
  }
  const Eigen::Vector3d s = a.colPivHouseholderQr().solve(b);
  return std::sqrt(0.25 * (s(0) * s(0) + s(1) * s(1)) - s(2));
}

// The car steered to `steer` standing still, then driven at `speed` by its rear wheels at the
// bicycle model's speeds (carWheelSpeeds): the radius of its reference point's path over half
// a turn once speed and steering have settled.
double drivenRadius(double steer, double speed) {
  const Scenario s = testing::carLot();
  DynamicsWorld world(s, s.start);
  world.setSteerTarget(steer);
  const double dt = world.timeStep();
  const double settle_s = std::abs(steer) / s.robot.max_steer_rate_radps + 0.5;
  for (long k = 0; k < std::lround(settle_s / dt); ++k) world.step();
  world.setWheelTargets(carWheelSpeeds(s.robot, speed, steer));
  for (long k = 0; k < std::lround(2.0 / dt); ++k) world.step();
  const double radius = s.robot.axle_distance_m / std::tan(std::abs(steer));
  const long half_turn = std::lround(kPi * radius / std::abs(speed) / dt);
  std::vector<Eigen::Vector2d> points;
  for (long k = 0; k < half_turn; ++k) {
    world.step();
    if (k % 24 == 0) points.push_back({world.robot().pose.x, world.robot().pose.y});
  }
  return fittedRadius(points);
}

TEST(CarBodyTest, ConstantSteeringDrivesTheBicycleModelsCircle) {
  const RobotDef car = midSizeCar();
  for (const double steer : {0.6, -0.3}) {
    const double predicted = car.axle_distance_m / std::tan(std::abs(steer));
    const double radius = drivenRadius(steer, 1.0);
    std::printf("steer %.2f rad at 1 m/s: radius %.4f m, predicted %.4f m (%.3f %%)\n", steer,
                radius, predicted, 100.0 * (radius / predicted - 1.0));
    EXPECT_NEAR(radius, predicted, 0.005 * predicted) << steer;
  }
}

TEST(CarBodyTest, SteeringReachesItsTargetAtTheRateLimit) {
  const Scenario s = testing::carLot();
  DynamicsWorld world(s, s.start);
  const double target = 0.4;
  world.setSteerTarget(target);
  const double dt = world.timeStep();
  const double rate = s.robot.max_steer_rate_radps;
  const double reach_s = target / rate;  // 0.8 s
  double worst = 0.0;
  double reached_at = -1.0;
  for (long k = 1; k <= std::lround((reach_s + 1.0) / dt); ++k) {
    world.step();
    const double t = static_cast<double>(k) * dt;
    const double predicted = std::min(target, rate * t);
    const double measured = world.robot().steer_rad;
    worst = std::max(worst, std::abs(measured - predicted));
    if (reached_at < 0.0 && std::abs(measured - target) < 1e-3) reached_at = t;
  }
  std::printf("steering step to %.2f rad: reached at %.4f s (predicted %.4f s), worst %.2e rad\n",
              target, reached_at, reach_s, worst);
  // Within 1 mrad of the ramp at every step; reaches the target within two steps of |delta| /
  // rate (the last mrad takes 2 ms at 0.5 rad/s).
  EXPECT_LT(worst, 1e-3);
  EXPECT_NEAR(reached_at, reach_s, 2.0 * dt + 1e-3 / rate);
  // The front wheels' own angles are Ackermann's.
  EXPECT_NEAR(world.robot().steer_rad, target, 1e-4);
}

TEST(CarBodyTest, StraightDrivingDoesNotDrift) {
  const Scenario s = testing::carLot({20.0, 50.0, 0.0});
  DynamicsWorld world(s, s.start);
  const double speed = 2.5;
  world.setWheelTargets(carWheelSpeeds(s.robot, speed, 0.0));
  const double dt = world.timeStep();
  double worst_lateral = 0.0;
  double worst_heading = 0.0;
  double x_at_10s = 0.0;
  const long steps = std::lround(20.0 / dt);
  for (long k = 1; k <= steps; ++k) {
    world.step();
    worst_lateral = std::max(worst_lateral, std::abs(world.robot().pose.y - s.start.y));
    worst_heading = std::max(worst_heading, std::abs(world.robot().pose.theta));
    if (k == steps / 2) x_at_10s = world.robot().pose.x;
  }
  const double travelled = world.robot().pose.x - x_at_10s;
  std::printf(
      "straight 20 s at 2.5 m/s: %.4f m in the last 10 s, speed %.6f m/s, lateral drift "
      "%.3e m, heading %.3e rad\n",
      travelled, world.robot().twist.v_mps, worst_lateral, worst_heading);
  // Rolling without slip: the rim speed, once the motors have reached it (torque-limited, in
  // well under a second).
  EXPECT_NEAR(travelled, speed * 10.0, 1e-3 * speed * 10.0);
  EXPECT_NEAR(world.robot().twist.v_mps, speed, 1e-3 * speed);
  // Open loop, nothing steers it back: off the line by at most 1e-4 of the distance (5 mm
  // over 50 m; 1.1 mm measured) and 0.1 mrad in heading (0.016 mrad measured). A build
  // without the transcription of Bullet's solver starts every row from zero (Bullet's own):
  // 3.6 mm and 0.144 mrad measured, a bias that more iterations do not remove (the same from
  // 50 to 400 a step; kExact cold-started gives it too), held to 0.2 mrad.
  const bool transcription = effectiveSolverKernel(SolverKernel::kFast) == SolverKernel::kFast;
  EXPECT_LT(worst_lateral, 1e-4 * speed * 20.0);
  EXPECT_LT(worst_heading, transcription ? 1e-4 : 2e-4);
}

}  // namespace
}  // namespace parksim
