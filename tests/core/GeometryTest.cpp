#include "parksim/core/model/Geometry.h"

#include <array>
#include <cmath>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "parksim/core/io/Text.h"
#include "parksim/core/model/Scenario.h"
#include "tests/support/ExactShapes.h"

namespace parksim {
namespace {

OrientedBox axisBox(double x0, double y0, double w, double h) {
  OrientedBox b;
  b.center = {x0 + 0.5 * w, y0 + 0.5 * h};
  b.half_extents = {0.5 * w, 0.5 * h};
  return b;
}

TEST(Geometry, FootprintReachesTenMillimetresAheadAndSeventyBehind) {
  const RobotDef robot;
  const OrientedBox fp = footprintAt(robot, {1.0, 2.0, 0.0});
  EXPECT_NEAR(fp.center.x() + fp.half_extents.x(), 1.010, 1e-12);
  EXPECT_NEAR(fp.center.x() - fp.half_extents.x(), 0.930, 1e-12);
  EXPECT_NEAR(fp.center.y() + fp.half_extents.y(), 2.0425, 1e-12);
  // Facing -y (head-in goal): front edge 10 mm below the reference point.
  const OrientedBox down = footprintAt(robot, {1.5, 0.04, -kPi / 2});
  double ymin = 1e9, ymax = -1e9;
  for (const auto& c : down.corners()) {
    ymin = std::min(ymin, c.y());
    ymax = std::max(ymax, c.y());
  }
  EXPECT_NEAR(ymin, 0.03, 1e-12);
  EXPECT_NEAR(ymax, 0.11, 1e-12);
}

TEST(Geometry, OverlapSeparationAndTouching) {
  const OrientedBox a = axisBox(0, 0, 1, 1);
  EXPECT_TRUE(boxesOverlap(a, axisBox(0.9, 0.9, 1, 1)));
  EXPECT_FALSE(boxesOverlap(a, axisBox(1.0, 0.0, 1, 1)));  // touching
  EXPECT_FALSE(boxesOverlap(a, axisBox(1.001, 0.0, 1, 1)));
  EXPECT_NEAR(separationAlongAxes(a, axisBox(1.25, 0.0, 1, 1)), 0.25, 1e-12);
  OrientedBox diamond;
  diamond.center = {1.0 + 0.5 * std::sqrt(2.0) + 0.01, 0.5};
  diamond.half_extents = {0.5, 0.5};
  diamond.yaw = kPi / 4;
  EXPECT_FALSE(boxesOverlap(a, diamond));
  diamond.center.x() -= 0.02;
  EXPECT_TRUE(boxesOverlap(a, diamond));
}

TEST(Geometry, FootprintRadiusIsTheFarthestCorner) {
  EXPECT_NEAR(footprintRadius(RobotDef{}), std::hypot(0.07, 0.0425), 1e-12);
}

}  // namespace
}  // namespace parksim

namespace parksim {
namespace {

// Core's separation for circles is exact and its polygon separation has the exact sign: both
// against the independent reference (Minkowski differences) on random boxes and shapes.
TEST(Geometry, CircleAndPolygonSeparationsAgreeWithTheIndependentReference) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> pos(-0.3, 0.3);
  std::uniform_real_distribution<double> size(0.01, 0.2);
  std::uniform_real_distribution<double> angle(-kPi, kPi);
  int overlapping = 0;
  for (int k = 0; k < 20000; ++k) {
    OrientedBox box;
    box.center = {pos(rng), pos(rng)};
    box.half_extents = {size(rng), size(rng)};
    box.yaw = angle(rng);
    const Obstacle circle =
        Obstacle::makeCircle("c", ObstacleKind::kBollard, {{pos(rng), pos(rng)}, size(rng)}, 0.1);
    EXPECT_NEAR(separation(box, circle), testing::exactSignedDistance(box, circle), 1e-12);
    const double phase = angle(rng);
    const Eigen::Vector2d c(pos(rng), pos(rng));
    std::vector<Eigen::Vector2d> vertices;
    const int n = 3 + k % 6;
    for (int i = 0; i < n; ++i) {
      const double a = phase + 2.0 * kPi * (i + 0.3 * (k % 3) / 3.0) / n;
      vertices.push_back(c + size(rng) * Eigen::Vector2d(std::cos(a), std::sin(a)));
    }
    if (!isStrictlyConvexCcw(vertices)) continue;
    const Obstacle polygon = Obstacle::makePolygon("p", ObstacleKind::kIsland, vertices, 0.1);
    const double exact = testing::exactSignedDistance(box, polygon);
    const double sat = separation(box, polygon);
    if (std::abs(exact) > 1e-12) {
      EXPECT_EQ(sat < 0.0, exact < 0.0) << k;
    }
    // Apart, separating axes give a lower bound of the gap and distance() the gap itself;
    // overlapping, the least penetration along an axis is the penetration depth.
    if (exact > 0.0) {
      EXPECT_LE(sat, exact + 1e-12);
      EXPECT_NEAR(distance(box, polygon), exact, 1e-12);
    } else {
      EXPECT_NEAR(sat, exact, 1e-12);
      EXPECT_EQ(distance(box, polygon), 0.0);
      ++overlapping;
    }
  }
  EXPECT_GT(overlapping, 1000);
}

// The overloads given the boxes' axes (for the search heuristic's grid) are the plain tests,
// to the last bit: the study's plans must not move.
TEST(Geometry, SeparationsWithGivenAxesAreTheSameToTheLastBit) {
  std::mt19937_64 rng(12);
  std::uniform_real_distribution<double> pos(-3.0, 3.0);
  std::uniform_real_distribution<double> size(0.05, 2.5);
  std::uniform_real_distribution<double> angle(-2.0 * kPi, 2.0 * kPi);
  auto randomBox = [&] {
    OrientedBox b;
    b.center = {pos(rng), pos(rng)};
    b.half_extents = {size(rng), size(rng)};
    b.yaw = angle(rng);
    return b;
  };
  for (int k = 0; k < 20000; ++k) {
    const OrientedBox a = randomBox();
    const OrientedBox b = randomBox();
    const BoxAxes own_a = axesOf(a);
    EXPECT_EQ(own_a.x, Eigen::Vector2d(std::cos(a.yaw), std::sin(a.yaw)));
    EXPECT_EQ(own_a.y, Eigen::Vector2d(-std::sin(a.yaw), std::cos(a.yaw)));
    EXPECT_EQ(separationAlongAxes(a, own_a, b, axesOf(b.yaw)), separationAlongAxes(a, b)) << k;
    const std::array<Eigen::Vector2d, 4> c = b.corners();
    const std::vector<Eigen::Vector2d> polygon(c.begin(), c.end());
    EXPECT_EQ(separationAlongAxes(a, own_a, polygon), separationAlongAxes(a, polygon)) << k;
  }
}

TEST(Geometry, ConvexityNeedsCounterClockwiseStrictTurnsAndOneRevolution) {
  const std::vector<Eigen::Vector2d> tri{{0, 0}, {1, 0}, {0, 1}};
  EXPECT_TRUE(isStrictlyConvexCcw(tri));
  EXPECT_FALSE(isStrictlyConvexCcw({{0, 0}, {0, 1}, {1, 0}}));          // clockwise
  EXPECT_FALSE(isStrictlyConvexCcw({{0, 0}, {1, 0}, {2, 0}, {0, 1}}));  // collinear
  EXPECT_FALSE(isStrictlyConvexCcw({{0, 0}, {1, 0}, {1, 0}, {0, 1}}));  // repeated
  // A pentagram turns left at every vertex but winds twice.
  std::vector<Eigen::Vector2d> star;
  for (int i = 0; i < 5; ++i) {
    const double a = 2.0 * kPi * (2 * i) / 5;
    star.emplace_back(std::cos(a), std::sin(a));
  }
  EXPECT_FALSE(isStrictlyConvexCcw(star));
  EXPECT_GT(signedDoubleArea(tri), 0.0);
}

TEST(Text, ControlCharactersAndInvalidBytesAreEscaped) {
  EXPECT_EQ(escapeText("plain caf\xc3\xa9"), "plain caf\xc3\xa9");
  EXPECT_EQ(escapeText("\x1b[31mred\n"), "\\x1b[31mred\\n");
  EXPECT_EQ(escapeText("bad \xff byte"), "bad \\xff byte");
  EXPECT_EQ(escapeText("c1 \xc2\x9b"), "c1 \\u009b");
  EXPECT_EQ(escapeText("overlong \xc0\xaf"), "overlong \\xc0\\xaf");
  EXPECT_TRUE(isPrintableUtf8("caf\xc3\xa9"));
  EXPECT_FALSE(isPrintableUtf8("a\tb"));
  EXPECT_FALSE(isValidUtf8("\xed\xa0\x80"));  // a surrogate
}

}  // namespace
}  // namespace parksim
