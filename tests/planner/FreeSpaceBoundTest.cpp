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

}  // namespace
}  // namespace parksim
