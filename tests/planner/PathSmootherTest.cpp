#include "parksim/planner/base/PathSmoother.h"

#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "parksim/core/io/Error.h"
#include "parksim/core/model/DiffDrive.h"
#include "parksim/planner/motion/MotionPrimitives.h"
#include "parksim/planner/steering/BalkcomMason.h"
#include "tests/support/StudyLot.h"

namespace parksim {
namespace {

using testing::SatChecker;

PathPiece piece(const Twist& motion, const RobotDef& robot) {
  return pieceOf(toWheelSpeeds(motion, robot), 1.0);
}

Pose2 endOf(const Pose2& start, const std::vector<PathPiece>& pieces, const RobotDef& robot) {
  return geometryOf(start, pieces, robot).points.back().pose;
}

Scenario emptyLot() {
  Scenario s;
  s.lot = {0.0, 0.0, 2.0, 2.0};
  return s;
}

TEST(PathSmoother, StraightensAZigzagAndKeepsItsEnds) {
  const Scenario s = emptyLot();
  const SatChecker checker(s);
  const MotionValidator validator(checker, s.robot, s.lot);
  const TimingLimits limits = timingLimits(s.robot, 0.2, 0.02);
  const PathSmoother smoother(s.robot, validator, limits);
  std::vector<PathPiece> zigzag;
  for (int k = 0; k < 6; ++k) {
    zigzag.push_back(piece({0.15, k % 2 ? 1.2 : -1.2}, s.robot));
    zigzag.push_back(piece({0.0, k % 2 ? -0.6 : 0.6}, s.robot));
  }
  const Pose2 start{0.3, 1.0, 0.0};
  std::mt19937_64 rng(1);
  PathSmoothingStats stats;
  const std::vector<PathPiece> smoothed = smoother.smooth(start, zigzag, 50, rng, &stats);
  EXPECT_GT(stats.shortcuts, 0);
  EXPECT_LT(stats.after_s, 0.8 * stats.before_s);
  EXPECT_NEAR(stats.after_s, timedDuration(smoothed, limits), 1e-12);
  EXPECT_NEAR(stats.before_s, timedDuration(zigzag, limits), 1e-12);
  const Pose2 a = endOf(start, zigzag, s.robot);
  const Pose2 b = endOf(start, smoothed, s.robot);
  EXPECT_NEAR(a.x, b.x, 1e-9);
  EXPECT_NEAR(a.y, b.y, 1e-9);
  EXPECT_NEAR(angleDiff(a.theta, b.theta), 0.0, 1e-9);
  EXPECT_TRUE(validator.isValid(geometryOf(start, smoothed, s.robot)));
  // In free space it gets as fast as the free-space optimum's path (or faster: arcs need no stop).
  const std::vector<PathPiece> optimum =
      piecesOf(balkcomMasonPath(start, a, 0.5 * s.robot.wheel_base_m), s.robot);
  EXPECT_LE(stats.after_s, timedDuration(optimum, limits) + 1e-9);
}

TEST(PathSmoother, TurnsACornerInPlaceIntoAnArc) {
  // A post inside the corner blocks the diagonal shortcut, not an arc around the corner.
  Scenario s = emptyLot();
  s.obstacles.push_back(
      Obstacle::makeBox("post", ObstacleKind::kBox, testing::cornerBox(0.55, 0.55, 0.1, 0.1), 0.1));
  const SatChecker checker(s);
  const MotionValidator validator(checker, s.robot, s.lot);
  const TimingLimits limits = timingLimits(s.robot, 0.2, 0.02);
  PathSmootherDef def;
  def.curve_radii_m.clear();  // fillets only
  const PathSmoother smoother(s.robot, validator, limits, def);
  const std::vector<PathPiece> corner{piece({0.6, 0.0}, s.robot), piece({0.0, kPi / 2}, s.robot),
                                      piece({0.6, 0.0}, s.robot)};
  std::mt19937_64 rng(1);
  PathSmoothingStats stats;
  const std::vector<PathPiece> smoothed = smoother.smooth({0.3, 0.3, 0.0}, corner, 0, rng, &stats);
  EXPECT_GE(stats.fillets, 1);
  EXPECT_LT(stats.after_s, stats.before_s);
  // An arc of one of the fillet radii turns where the robot turned in place.
  bool arc = false;
  for (const PathPiece& p : smoothed) {
    const Twist tw = toTwist(
        {p.direction.left_radps * p.travel_rad, p.direction.right_radps * p.travel_rad}, s.robot);
    if (std::abs(tw.omega_radps) < 1e-9 || std::abs(tw.v_mps) < 1e-9) continue;
    for (double r : def.fillet_radii_m) arc = arc || std::abs(tw.v_mps / tw.omega_radps - r) < 1e-9;
  }
  EXPECT_TRUE(arc);
  EXPECT_TRUE(validator.isValid(geometryOf({0.3, 0.3, 0.0}, smoothed, s.robot)));
}

TEST(PathSmoother, KeepsWhatObstaclesBlock) {
  // The study lot's wall between start and goal: the direct shortcut collides, so the detour
  // through the gap stays, and whatever is kept is valid.
  const Scenario s = testing::studyLot();
  const SatChecker checker(s);
  const MotionValidator validator(checker, s.robot, s.lot);
  const TimingLimits limits = timingLimits(s.robot, 0.2, 0.02);
  const PathSmoother smoother(s.robot, validator, limits);
  // From (0.2, 0.3) north to y 0.5, east through the gap past the wall, south to (0.75, 0.3).
  const std::vector<PathPiece> detour{piece({0.0, kPi / 2}, s.robot),  piece({0.2, 0.0}, s.robot),
                                      piece({0.0, -kPi / 2}, s.robot), piece({0.55, 0.0}, s.robot),
                                      piece({0.0, -kPi / 2}, s.robot), piece({0.2, 0.0}, s.robot)};
  const Pose2 start{0.2, 0.3, 0.0};
  ASSERT_TRUE(validator.isValid(geometryOf(start, detour, s.robot)));
  std::mt19937_64 rng(5);
  const std::vector<PathPiece> smoothed = smoother.smooth(start, detour, 100, rng);
  EXPECT_TRUE(validator.isValid(geometryOf(start, smoothed, s.robot)));
  EXPECT_LE(timedDuration(smoothed, limits), timedDuration(detour, limits));
  // Same seed, same result.
  std::mt19937_64 again(5);
  const std::vector<PathPiece> repeat = smoother.smooth(start, detour, 100, again);
  ASSERT_EQ(repeat.size(), smoothed.size());
  for (std::size_t i = 0; i < repeat.size(); ++i) {
    EXPECT_EQ(repeat[i].travel_rad, smoothed[i].travel_rad);
    EXPECT_EQ(repeat[i].direction, smoothed[i].direction);
  }
}

TEST(PathSmoother, RejectsBadDefinitions) {
  const Scenario s = emptyLot();
  const SatChecker checker(s);
  const MotionValidator validator(checker, s.robot, s.lot);
  PathSmootherDef def;
  def.fillet_radii_m = {0.1, 0.0};
  EXPECT_THROW(PathSmoother(s.robot, validator, {}, def), Error);
  const PathSmoother ok(s.robot, validator, {});
  std::mt19937_64 rng(1);
  EXPECT_THROW(ok.smooth({}, {}, -1, rng), Error);
}

}  // namespace
}  // namespace parksim
