#include "parksim/planner/search/FootprintFit.h"

#include <random>

#include <gtest/gtest.h>

#include "tests/support/StudyLot.h"

namespace parksim {
namespace {

// The exact footprint check (separating axes, tests/support) at the same eight headings.
bool fitsExactly(const testing::SatChecker& checker, double x, double y, double margin) {
  for (int h = 0; h < 8; ++h) {
    if (checker.isFree(Pose2{x, y, h * kPi / 4.0}, margin)) return true;
  }
  return false;
}

TEST(FootprintFit, ACompoundObstacleFitsLikeItsPartsEachAnObstacle) {
  // A U and an L as compound obstacles, against the same parts as convex polygons.
  const std::vector<std::vector<Eigen::Vector2d>> u{
      {{0.6, 0.3}, {1.0, 0.3}, {1.0, 0.4}, {0.6, 0.4}},
      {{0.6, 0.4}, {0.7, 0.4}, {0.7, 0.8}, {0.6, 0.8}},
      {{0.9, 0.4}, {1.0, 0.4}, {1.0, 0.8}, {0.9, 0.8}}};
  const std::vector<std::vector<Eigen::Vector2d>> l{
      {{1.3, 0.2}, {1.6, 0.2}, {1.35, 0.3}}, {{1.3, 0.2}, {1.35, 0.3}, {1.35, 0.7}, {1.3, 0.7}}};
  Scenario compound;
  Scenario separate;
  for (const auto* parts : {&u, &l}) {
    compound.obstacles.push_back(
        Obstacle::makeCompound("c", ObstacleKind::kWall, CompoundShape::make(*parts, {}), 0.1));
    for (const auto& part : *parts) {
      separate.obstacles.push_back(Obstacle::makePolygon("p", ObstacleKind::kWall, part, 0.1));
    }
  }
  const FootprintFit a(compound.obstacles, compound.robot, 0.0005);
  const FootprintFit b(separate.obstacles, separate.robot, 0.0005);
  std::mt19937_64 rng(8);
  std::uniform_real_distribution<double> x(0.4, 1.8), y(0.0, 1.0);
  int blocked = 0;
  for (int i = 0; i < 20000; ++i) {
    const double px = x(rng);
    const double py = y(rng);
    ASSERT_EQ(a.fitsSomeHeading(px, py), b.fitsSomeHeading(px, py)) << px << ", " << py;
    blocked += !a.fitsSomeHeading(px, py);
  }
  EXPECT_GT(blocked, 500);
}

TEST(FootprintFit, AgreesWithTheExactCheckAtEveryHeadingTested) {
  Scenario s = testing::studyLot();
  // A bollard and a polygon as well as the study's boxes.
  s.obstacles.push_back(
      Obstacle::makeCircle("bollard", ObstacleKind::kBollard, {{0.3, 0.7}, 0.03}, 0.1));
  s.obstacles.push_back(Obstacle::makePolygon("island", ObstacleKind::kIsland,
                                              {{1.0, 0.85}, {1.2, 0.8}, {1.15, 0.95}}, 0.1));
  const testing::SatChecker checker(s);
  const FootprintFit fit(s.obstacles, s.robot, 0.0005);
  std::mt19937_64 rng(4);
  std::uniform_real_distribution<double> x(-0.1, 1.9), y(-0.1, 1.3);
  int blocked = 0;
  for (int i = 0; i < 20000; ++i) {
    const double px = x(rng);
    const double py = y(rng);
    const bool expected = fitsExactly(checker, px, py, 0.0005);
    ASSERT_EQ(fit.fitsSomeHeading(px, py), expected) << px << ", " << py;
    if (!expected) ++blocked;
  }
  EXPECT_GT(blocked, 1000);
}

TEST(FootprintFit, ObstaclesUnderTheChassisDoNotCount) {
  Scenario s;
  s.obstacles.push_back(Obstacle::makeBox("line", ObstacleKind::kCurb,
                                          testing::cornerBox(0.0, 0.0, 1.0, 1.0), 0.001));
  EXPECT_TRUE(FootprintFit(s.obstacles, s.robot, 0.0).fitsSomeHeading(0.5, 0.5));
}

}  // namespace
}  // namespace parksim
