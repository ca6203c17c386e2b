#include "parksim/planner/base/FreeSpaceBound.h"

#include <random>

#include <gtest/gtest.h>

#include "parksim/planner/steering/BalkcomMasonSteering.h"

namespace parksim {
namespace {

TEST(FreeSpaceBound, StraightAheadIsTheFastestTrapezoid) {
  const RobotDef robot;
  const TimingLimits l = timingLimits(robot, 0.2, 0.1);
  // 1 m: 50 rad; periods at 4, 8, ..., 8, 4 rad/s: 0.1 (8 (n - 1)) >= 50 -> n = 64 (6.4 s), and
  // the exact timing of the straight line takes exactly that.
  EXPECT_NEAR(freeSpaceDurationBound({0, 0, 0}, {1, 0, 0}, robot, l), 6.4, 1e-12);
  EXPECT_NEAR(timedDuration({{{1.0, 1.0}, 50.0}}, l), 6.4, 1e-12);
  EXPECT_EQ(freeSpaceDurationBound({0.3, 0.2, 1.0}, {0.3, 0.2, 1.0}, robot, l), 0.0);
}

TEST(FreeSpaceBound, NoTimedPathIsFaster) {
  const RobotDef robot;
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> pos(0.0, 1.5), ang(-kPi, kPi);
  for (double period : {0.1, 0.02}) {
    const TimingLimits l = timingLimits(robot, 0.2, period);
    BalkcomMasonDef def;
    def.period_s = period;
    def.speed_fraction = 0.8;
    const BalkcomMasonSteering fastest(robot, def);
    for (int i = 0; i < 200; ++i) {
      const Pose2 a{pos(rng), pos(rng), ang(rng)};
      const Pose2 b{pos(rng), pos(rng), ang(rng)};
      const double bound = freeSpaceDurationBound(a, b, robot, l);
      const double timed = fastest.steer(a, {}, b, SteerMode::kExact).trajectory.duration();
      EXPECT_LE(bound, timed + 1e-9);
      // The free-space optimum at full speed, plus the stops it needs, is not far above.
      EXPECT_GE(bound, 0.5 * timed);
    }
  }
}

// A car's bound: its shortest path, the Reeds-Shepp curve at its tightest radius, from rest to
// rest in 0.1 s rows at 2.5 m/s and 1 m/s^2 (speeds 0.1 k m/s, full speed from the 25th row).
TEST(FreeSpaceBound, ACarsIsItsShortestPathAtItsLimits) {
  const RobotDef car = midSizeCar();
  // Straight ahead 20.1 m: n rows of a full trapezoid cover (2 x 0.1 x (1 + ... + 24) +
  // 2.5 (n - 48)) x 0.1 = 0.25 n - 6 m >= 20.1 at n = 105.
  EXPECT_NEAR(carFreeSpaceDurationBound({0, 0, 0}, {20.1, 0, 0}, car, 0.1), 10.5, 1e-9);
  // A quarter turn on the tightest circle: pi R / 2 = 4.72 m, too short to reach full speed;
  // n = 2m + 1 rows of a triangle cover 0.01 (m + 1)^2 m: 4.84 at n = 43, 4.41 at n = 41, and
  // 4.62 (0.01 m (m + 1), m = 21) at n = 42.
  const double r = car.minTurningRadius();
  ASSERT_LT(0.01 * 21 * 22, 0.5 * kPi * r);
  ASSERT_GE(0.01 * 22 * 22, 0.5 * kPi * r);
  EXPECT_NEAR(carFreeSpaceDurationBound({0, 0, 0}, {r, r, 0.5 * kPi}, car, 0.1), 4.3, 1e-9);
  EXPECT_EQ(carFreeSpaceDurationBound({3, 2, 1}, {3, 2, 1}, car, 0.1), 0.0);
}

}  // namespace
}  // namespace parksim
