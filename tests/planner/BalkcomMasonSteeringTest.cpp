#include "parksim/planner/steering/BalkcomMasonSteering.h"

#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "parksim/core/io/Error.h"
#include "parksim/planner/steering/BalkcomMason.h"
#include "tests/support/PlanChecks.h"

namespace parksim {
namespace {

using testing::expectConsistentWithLimits;

TEST(BalkcomMasonSteering, ReachesTargetsExactlyWithinTheLimits) {
  const RobotDef robot;
  const BalkcomMasonSteering steering(robot);
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> pos(0.0, 1.0), ang(-kPi, kPi), wheel(-10.0, 10.0);
  for (int i = 0; i < 200; ++i) {
    const Pose2 from{pos(rng), pos(rng), ang(rng)};
    const Pose2 to{pos(rng), pos(rng), ang(rng)};
    const WheelSpeeds arriving = i % 3 == 0 ? WheelSpeeds{wheel(rng), wheel(rng)} : WheelSpeeds{};
    const SteerResult r = steering.steer(from, arriving, to, SteerMode::kExact);
    ASSERT_TRUE(r.reached);
    EXPECT_EQ(r.trajectory.points.front().pose, from);
    EXPECT_EQ(r.trajectory.points.back().pose, to);
    expectConsistentWithLimits(r.trajectory, robot, arriving, 1e-9);
    if (arriving == WheelSpeeds{}) {
      // Every period turns in place or drives straight: the fastest free-space paths do only
      // that, and its wheels turn exactly as far as the Balkcom-Mason cost says.
      double travel = 0.0;
      for (std::size_t k = 0; k + 1 < r.trajectory.points.size(); ++k) {
        const Twist tw = toTwist(r.trajectory.points[k].wheels, robot);
        EXPECT_TRUE(std::abs(tw.v_mps) < 1e-12 || std::abs(tw.omega_radps) < 1e-12);
        const WheelSpeeds& w = r.trajectory.points[k].wheels;
        const double dt = r.trajectory.points[k + 1].t_s - r.trajectory.points[k].t_s;
        travel += std::max(std::abs(w.left_radps), std::abs(w.right_radps)) * dt;
      }
      EXPECT_NEAR(travel,
                  balkcomMasonCost(from, to, 0.5 * robot.wheel_base_m) / robot.wheel_radius_m,
                  1e-9);
    }
  }
}

TEST(BalkcomMasonSteering, FixedHorizonCutsThePath) {
  const RobotDef robot;
  const BalkcomMasonSteering steering(robot);
  const SteerResult far = steering.steer({0, 0, 0}, {}, {1.0, 0.3, 1.0}, SteerMode::kFixedHorizon);
  EXPECT_FALSE(far.reached);
  EXPECT_NEAR(far.trajectory.duration(), 1.0, 1e-9);
  const SteerResult near = steering.steer({0, 0, 0}, {}, {0.01, 0, 0}, SteerMode::kFixedHorizon);
  EXPECT_TRUE(near.reached);
}

TEST(BalkcomMasonSteering, RejectsBadDefinitions) {
  const RobotDef robot;
  BalkcomMasonDef def;
  def.speed_fraction = 0.0;
  EXPECT_THROW(BalkcomMasonSteering(robot, def), Error);
  def = {};
  def.period_s = 0.0;
  EXPECT_THROW(BalkcomMasonSteering(robot, def), Error);
}

}  // namespace
}  // namespace parksim
