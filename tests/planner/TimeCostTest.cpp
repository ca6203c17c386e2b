#include "parksim/planner/motion/TimeCost.h"

#include <random>

#include <gtest/gtest.h>

#include "parksim/core/model/DiffDrive.h"
#include "parksim/planner/steering/BalkcomMason.h"

namespace parksim {
// Named, not anonymous: its program is compiled as one unity batch, where another file's
// helpers of the same names would meet these.
namespace time_cost_test {

PathPiece piece(const Twist& motion, const RobotDef& robot) {
  return pieceOf(toWheelSpeeds(motion, robot), 1.0);
}

TEST(TimeCost, PiecesAtFullSpeedAndJunctionsByTheirStops) {
  const RobotDef robot;
  const TimingLimits limits = timingLimits(robot, 0.2, 0.02);
  const TimeCostModel cost(limits);
  // 1 m straight: 50 rad of wheel travel at 8 rad/s.
  const PathPiece straight = piece({1.0, 0.0}, robot);
  EXPECT_NEAR(cost.pieceTime(straight), 50.0 / 8.0, 1e-12);
  // A turn in place of pi: h pi / r of wheel travel.
  EXPECT_NEAR(cost.pieceTime(piece({0.0, kPi}, robot)), 0.0425 * kPi / 0.02 / 8.0, 1e-12);
  // No loss between pieces of one direction; a cusp or a turn in place after driving changes a
  // wheel's share by 2: passing at e = 0.8 / 2 rad/s costs (8 - 0.4)^2 / (40 * 8) s.
  EXPECT_EQ(cost.junctionTime(straight.direction, straight.direction), 0.0);
  const PathPiece back = piece({-1.0, 0.0}, robot);
  EXPECT_NEAR(cost.junctionTime(straight.direction, back.direction), 7.6 * 7.6 / 320.0, 1e-12);
  // From rest, one ramp: half of the two-sided loss at e = 0.8.
  EXPECT_NEAR(cost.junctionTime({}, straight.direction), 0.5 * 7.2 * 7.2 / 320.0, 1e-12);
}

TEST(TimeCost, EstimateIsCloseToTheExactTiming) {
  const RobotDef robot;
  const TimingLimits limits = timingLimits(robot, 0.2, 0.02);
  const TimeCostModel cost(limits);
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> pos(0.0, 1.0), ang(-kPi, kPi);
  for (int i = 0; i < 200; ++i) {
    const Pose2 a{pos(rng), pos(rng), ang(rng)};
    const Pose2 b{pos(rng), pos(rng), ang(rng)};
    const std::vector<PathPiece> pieces =
        piecesOf(balkcomMasonPath(a, b, 0.5 * robot.wheel_base_m), robot);
    if (pieces.empty()) continue;
    const double exact = timedDuration(pieces, limits);
    // Never below the pieces at full speed; within a few periods per piece of the exact timing.
    double full_speed = 0.0;
    for (const PathPiece& p : pieces) full_speed += cost.pieceTime(p);
    EXPECT_GE(exact, full_speed - 1e-9);
    EXPECT_NEAR(cost.duration(pieces), exact, 0.1 * static_cast<double>(pieces.size() + 1));
  }
}

}  // namespace time_cost_test
}  // namespace parksim
