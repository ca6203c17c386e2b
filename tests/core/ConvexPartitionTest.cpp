#include "parksim/core/geometry/ConvexPartition.h"

#include <cmath>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "parksim/core/geometry/ExactOrientation.h"
#include "parksim/core/model/Scenario.h"
#include "tests/support/PolygonOracle.h"

namespace parksim {
namespace {

using testing::Ring;

bool strictlyInsideConvex(const Ring& part, const Eigen::Vector2d& p) {
  for (std::size_t i = 0; i < part.size(); ++i) {
    if (orientation(part[i], part[(i + 1) % part.size()], p) <= 0) return false;
  }
  return true;
}

double ringArea(const Ring& r) {
  double s = 0.0;
  for (std::size_t i = 0; i < r.size(); ++i) {
    s += r[i].x() * r[(i + 1) % r.size()].y() - r[i].y() * r[(i + 1) % r.size()].x();
  }
  return 0.5 * s;
}

void expectStrictlyConvexCcw(const std::vector<Ring>& parts) {
  for (const Ring& part : parts) {
    ASSERT_GE(part.size(), 3u);
    for (std::size_t i = 0; i < part.size(); ++i) {
      const std::size_t n = part.size();
      EXPECT_GT(orientation(part[(i + n - 1) % n], part[i], part[(i + 1) % n]), 0);
    }
  }
}

TEST(ConvexPartition, AnLShapeIsTwoParts) {
  const PolygonWithHoles l{{{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}}, {}};
  const std::vector<Ring> parts = convexPartition(l);
  expectStrictlyConvexCcw(parts);
  EXPECT_EQ(parts.size(), 2u);
  double area = 0.0;
  for (const Ring& p : parts) area += ringArea(p);
  EXPECT_DOUBLE_EQ(area, 3.0);
}

TEST(ConvexPartition, AConvexPolygonStaysOnePartInEitherWinding) {
  const Ring hexagon{{1, 0}, {0.5, 0.8}, {-0.5, 0.8}, {-1, 0}, {-0.5, -0.8}, {0.5, -0.8}};
  Ring clockwise(hexagon.rbegin(), hexagon.rend());
  for (const Ring& ring : {hexagon, clockwise}) {
    const std::vector<Ring> parts = convexPartition({ring, {}});
    ASSERT_EQ(parts.size(), 1u);
    EXPECT_EQ(parts[0].size(), 6u);
    EXPECT_NEAR(ringArea(parts[0]), ringArea(hexagon), 1e-12);
  }
}

TEST(ConvexPartition, CollinearVerticesAreDroppedNotKept) {
  // A square with a vertex in the middle of each side: one part of four corners.
  const Ring square{{0, 0}, {1, 0}, {2, 0}, {2, 1}, {2, 2}, {1, 2}, {0, 2}, {0, 1}};
  const std::vector<Ring> parts = convexPartition({square, {}});
  ASSERT_EQ(parts.size(), 1u);
  EXPECT_EQ(parts[0].size(), 4u);
}

TEST(ConvexPartition, ASquareRingCoversEverythingButItsHole) {
  const PolygonWithHoles frame{{{0, 0}, {4, 0}, {4, 4}, {0, 4}},
                               {{{1, 1}, {3, 1}, {3, 3}, {1, 3}}}};
  const std::vector<Ring> parts = convexPartition(frame);
  expectStrictlyConvexCcw(parts);
  double area = 0.0;
  for (const Ring& p : parts) area += ringArea(p);
  EXPECT_DOUBLE_EQ(area, 12.0);
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-0.5, 4.5);
  for (int k = 0; k < 20000; ++k) {
    const Eigen::Vector2d p(u(rng), u(rng));
    int covering = 0;
    for (const Ring& part : parts) covering += strictlyInsideConvex(part, p);
    EXPECT_EQ(covering, testing::insideRings({frame.outer, frame.holes[0]}, p) ? 1 : 0)
        << p.transpose();
  }
}

// Random simple polygons with holes: every point is covered by exactly one part when inside and
// by none when outside, and the parts' areas add up.
TEST(ConvexPartition, RandomPolygonsWithHolesArePartitionedExactly) {
  std::mt19937_64 rng(32);
  std::uniform_real_distribution<double> u(-1.2, 1.2);
  int tested = 0;
  for (int seed = 0; seed < 150; ++seed) {
    PolygonWithHoles region;
    region.outer = testing::starRing(rng, {0, 0}, 6 + seed % 40, 0.6, 1.0);
    const int holes = seed % 4;
    for (int h = 0; h < holes; ++h) {
      const double a = 2.0 * 3.14159265358979323846 * h / std::max(holes, 1) + 0.3;
      region.holes.push_back(testing::starRing(rng, 0.3 * Eigen::Vector2d(std::cos(a), std::sin(a)),
                                               3 + seed % 7, 0.03, 0.12));
    }
    if (regionProblem(region)) continue;  // holes that happened to meet
    ++tested;
    const std::vector<Ring> parts = convexPartition(region);
    expectStrictlyConvexCcw(parts);
    std::vector<Ring> rings{region.outer};
    rings.insert(rings.end(), region.holes.begin(), region.holes.end());
    double area = std::abs(ringArea(region.outer));
    for (const Ring& h : region.holes) area -= std::abs(ringArea(h));
    double sum = 0.0;
    for (const Ring& p : parts) sum += ringArea(p);
    EXPECT_NEAR(sum, area, 1e-12);
    for (int k = 0; k < 2000; ++k) {
      const Eigen::Vector2d p(u(rng), u(rng));
      int covering = 0;
      for (const Ring& part : parts) covering += strictlyInsideConvex(part, p);
      ASSERT_EQ(covering, testing::insideRings(rings, p) ? 1 : 0)
          << "seed " << seed << " point " << p.transpose();
    }
  }
  EXPECT_GT(tested, 120);
}

// The done-when check of issue 32: a non-convex obstacle answers "does the footprint touch it"
// like an exact point-in-polygon test, on 10^5 random poses.
TEST(ConvexPartition, FootprintQueriesAgreeWithPointInPolygonOnOneHundredThousandPoses) {
  std::mt19937_64 rng(7);
  const PolygonWithHoles region = testing::starWithTwoHoles(rng, {1.0, 1.0}, 48);
  ASSERT_FALSE(regionProblem(region));
  const Obstacle obstacle = Obstacle::makeCompound(
      "star", ObstacleKind::kIsland, CompoundShape::make(convexPartition(region), {}), 0.1);
  const std::vector<Ring> rings{region.outer, region.holes[0], region.holes[1]};
  const RobotDef robot;
  std::uniform_real_distribution<double> xy(-0.05, 2.05);
  std::uniform_real_distribution<double> yaw(-3.14159, 3.14159);
  int overlapping = 0;
  for (int k = 0; k < 100000; ++k) {
    const OrientedBox footprint = footprintAt(robot, {xy(rng), xy(rng), yaw(rng)});
    const bool oracle = testing::footprintOverlapsRings(footprint, rings);
    ASSERT_EQ(separation(footprint, obstacle) < 0.0, oracle) << "pose " << k;
    overlapping += oracle;
  }
  // Both answers are common, so agreement means something.
  EXPECT_GT(overlapping, 20000);
  EXPECT_LT(overlapping, 80000);
}

}  // namespace
}  // namespace parksim
