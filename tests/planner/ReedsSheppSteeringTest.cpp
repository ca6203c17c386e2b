#include "parksim/planner/steering/ReedsSheppSteering.h"

#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "parksim/core/io/Error.h"
#include "tests/support/PlanChecks.h"

namespace parksim {
namespace {

using testing::expectConsistentWithLimits;

TEST(ReedsSheppSteering, ReachesTargetsExactlyAlongTheShortestCurve) {
  const RobotDef robot;
  const ReedsSheppSteering steering(robot);
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> pos(0.0, 1.0), ang(-kPi, kPi), wheel(-10.0, 10.0);
  int with_cusps = 0;
  for (int i = 0; i < 300; ++i) {
    const Pose2 from{pos(rng), pos(rng), ang(rng)};
    const Pose2 to{pos(rng), pos(rng), ang(rng)};
    const WheelSpeeds arriving = i % 3 == 0 ? WheelSpeeds{wheel(rng), wheel(rng)} : WheelSpeeds{};
    const SteerResult r = steering.steer(from, arriving, to, SteerMode::kExact);
    ASSERT_TRUE(r.reached);
    EXPECT_EQ(r.trajectory.points.front().pose, from);
    EXPECT_EQ(r.trajectory.points.back().pose, to);
    expectConsistentWithLimits(r.trajectory, robot, arriving, 1e-9);
    if (arriving == WheelSpeeds{}) {
      // The driven length is the curve's length: every arc has the chosen radius.
      EXPECT_NEAR(r.trajectory.pathLength(robot), steering.distance(from, to), 1e-9);
      for (std::size_t k = 0; k + 1 < r.trajectory.points.size(); ++k) {
        const Twist tw = toTwist(r.trajectory.points[k].wheels, robot);
        if (std::abs(tw.omega_radps) > 1e-9) {
          EXPECT_NEAR(std::abs(tw.v_mps / tw.omega_radps), 0.05, 1e-9);
        }
      }
      if (r.trajectory.cusps(robot) > 0) ++with_cusps;
    }
  }
  EXPECT_GT(with_cusps, 50);
}

TEST(ReedsSheppSteering, LengthsAreReedsSheppLengths) {
  // Straight ahead: the distance; a half turn to the side at the radius: pi r; parallel shift
  // sideways by 2r needs a reversal but no more than 2 pi r.
  const RobotDef robot;
  const ReedsSheppSteering s(robot);
  EXPECT_NEAR(s.distance({0, 0, 0}, {0.3, 0, 0}), 0.3, 1e-12);
  EXPECT_NEAR(s.distance({0, 0, 0}, {0, 0.1, kPi}), kPi * 0.05, 1e-12);
  EXPECT_NEAR(s.distance({0, 0, 0}, {-0.3, 0, 0}), 0.3, 1e-12);
  const double shift = s.distance({0, 0, 0}, {0, 0.1, 0});
  EXPECT_GT(shift, 0.1);
  EXPECT_LE(shift, 2.0 * kPi * 0.05);
}

TEST(ReedsSheppSteering, FixedHorizonCutsThePath) {
  const RobotDef robot;
  const ReedsSheppSteering s(robot);
  const SteerResult r = s.steer({0, 0, 0}, {}, {2.0, 0, 0}, SteerMode::kFixedHorizon);
  EXPECT_FALSE(r.reached);
  EXPECT_NEAR(r.trajectory.duration(), 1.0, 1e-12);
  EXPECT_TRUE(s.steer({0, 0, 0}, {}, {0.05, 0, 0}, SteerMode::kFixedHorizon).reached);
}

TEST(ReedsSheppSteering, RejectsBadRadius) {
  ReedsSheppDef def;
  def.turning_radius_m = 0.0;
  EXPECT_THROW(ReedsSheppSteering(RobotDef{}, def), Error);
}

}  // namespace
}  // namespace parksim
