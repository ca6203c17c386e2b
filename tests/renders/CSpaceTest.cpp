#include "parksim/renders/plots/CSpace.h"

#include <gtest/gtest.h>

#include <cmath>

#include "parksim/core/geometry/Angle.h"
#include "parksim/core/model/Geometry.h"
#include "parksim/core/model/Scenario.h"
#include "tests/support/ExactShapes.h"

namespace parksim {
namespace {

OrientedBox makeBox(double cx, double cy, double sx, double sy, double yaw) {
  return OrientedBox{{cx, cy}, {0.5 * sx, 0.5 * sy}, yaw};
}

double area(const std::vector<Eigen::Vector2d>& poly) {
  double a = 0.0;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const Eigen::Vector2d& p = poly[i];
    const Eigen::Vector2d& q = poly[(i + 1) % poly.size()];
    a += p.x() * q.y() - q.x() * p.y();
  }
  return 0.5 * a;
}

TEST(CSpaceTest, AlignedSliceIsTheAnalyticRectangle) {
  // At heading 0 the footprint spans [f - L, f] x [-W/2, W/2] around the reference point, so it
  // overlaps the obstacle [x0, x1] x [y0, y1] exactly for reference points in
  // (x0 - f, x1 + L - f) x (y0 - W/2, y1 + W/2).
  const RobotDef robot;
  const OrientedBox obstacle = makeBox(1.0, 0.5, 0.2, 0.1, 0.0);
  const std::vector<Eigen::Vector2d> slice = cspaceSlice(obstacle, robot, 0.0);
  ASSERT_EQ(slice.size(), 4u);
  const double f = robot.front_overhang_m;
  const double x_lo = 0.9 - f;
  const double x_hi = 1.1 + robot.length_m - f;
  const double y_lo = 0.45 - 0.5 * robot.width_m;
  const double y_hi = 0.55 + 0.5 * robot.width_m;
  for (const Eigen::Vector2d& v : slice) {
    EXPECT_TRUE(std::abs(v.x() - x_lo) < 1e-12 || std::abs(v.x() - x_hi) < 1e-12) << v.transpose();
    EXPECT_TRUE(std::abs(v.y() - y_lo) < 1e-12 || std::abs(v.y() - y_hi) < 1e-12) << v.transpose();
  }
  EXPECT_NEAR(area(slice), (x_hi - x_lo) * (y_hi - y_lo), 1e-12);
}

TEST(CSpaceTest, SliceMatchesTheOverlapTestAtSamplePoints) {
  // The study's Fig. 5 heading, against a rotated obstacle: inside the slice exactly where the
  // footprint at that reference point overlaps the obstacle (exact separating-axis test).
  const RobotDef robot;
  const OrientedBox obstacle = makeBox(0.6, 0.4, 0.3, 0.12, degToRad(20.0));
  for (double theta_deg : {-60.0, 0.0, 37.0, 90.0, 180.0}) {
    const double theta = degToRad(theta_deg);
    const std::vector<Eigen::Vector2d> slice = cspaceSlice(obstacle, robot, theta);
    ASSERT_GE(slice.size(), 4u);
    ASSERT_LE(slice.size(), 8u);
    EXPECT_GT(area(slice), 0.0);  // counter-clockwise
    int inside = 0;
    int outside = 0;
    for (double x = 0.3; x <= 0.9; x += 0.00731) {
      for (double y = 0.15; y <= 0.65; y += 0.00677) {
        const OrientedBox fp = footprintAt(robot, {x, y, theta});
        // Points within a micrometre of the boundary could go either way by rounding.
        if (std::abs(separationAlongAxes(fp, obstacle)) < 1e-6) continue;
        const bool overlaps = boxesOverlap(fp, obstacle);
        EXPECT_EQ(insideConvex(slice, {x, y}), overlaps)
            << "theta " << theta_deg << " at (" << x << ", " << y << ")";
        (overlaps ? inside : outside)++;
      }
    }
    EXPECT_GT(inside, 200);
    EXPECT_GT(outside, 200);
  }
}

TEST(CSpaceTest, GeneralSliceIsAnOctagonWithTheMinkowskiArea) {
  // Area of the Minkowski sum of rectangles a x b and c x d at relative angle phi, |A| + |B| plus
  // twice their mixed area: ab + cd + (ad + bc)|cos phi| + (ac + bd)|sin phi|.
  const RobotDef robot;
  const double a = 0.3;
  const double b = 0.12;
  const double c = robot.length_m;
  const double d = robot.width_m;
  const OrientedBox obstacle = makeBox(0.0, 0.0, a, b, 0.0);
  const double phi = degToRad(-60.0);
  const std::vector<Eigen::Vector2d> slice = cspaceSlice(obstacle, robot, phi);
  EXPECT_EQ(slice.size(), 8u);
  const double expected = a * b + c * d + (a * d + b * c) * std::abs(std::cos(phi)) +
                          (a * c + b * d) * std::abs(std::sin(phi));
  EXPECT_NEAR(area(slice), expected, 1e-12);
}

TEST(CSpaceTest, SlicesDifferFromOneHullOverAllHeadings) {
  // The study's single hull over every heading claims collisions that no heading has: a
  // reference point inside that hull can be free at the heading asked about.
  const RobotDef robot;
  const OrientedBox obstacle = makeBox(1.0, 0.5, 0.2, 0.1, 0.0);
  std::vector<Eigen::Vector2d> all;
  for (int k = 0; k < 100; ++k) {
    const auto s = cspaceSlice(obstacle, robot, -kPi + 2.0 * kPi * k / 100);
    all.insert(all.end(), s.begin(), s.end());
  }
  const std::vector<Eigen::Vector2d> union_hull = convexHull(all);
  const std::vector<Eigen::Vector2d> slice = cspaceSlice(obstacle, robot, 0.0);
  const Eigen::Vector2d p(1.0, 0.5 + 0.05 + 0.5 * robot.width_m + 0.02);  // north of the slice
  EXPECT_TRUE(insideConvex(union_hull, p));
  EXPECT_FALSE(insideConvex(slice, p));
  EXPECT_FALSE(boxesOverlap(footprintAt(robot, {p.x(), p.y(), 0.0}), obstacle));
}

TEST(CSpaceTest, ConvexHullDropsInteriorAndCollinearPoints) {
  const std::vector<Eigen::Vector2d> hull =
      convexHull({{0, 0}, {1, 0}, {2, 0}, {2, 1}, {1, 0.5}, {0, 1}, {1, 1}, {0, 0}});
  EXPECT_EQ(hull.size(), 4u);
  EXPECT_NEAR(area(hull), 2.0, 1e-15);
}

// Polygons: the slice is exact; a reference point inside it (by more than a micrometre) puts
// the footprint into the polygon, one outside it keeps them apart, by the independent exact
// distance. Circles: every vertex of the slice lies on the exact boundary (distance 0), and
// the chords cut inside it by at most r (1 - cos(pi / 32)).
TEST(CSpaceTest, PolygonAndCircleSlicesAreExact) {
  const RobotDef robot;
  const Obstacle polygon = Obstacle::makePolygon(
      "p", ObstacleKind::kIsland, {{0.9, 0.4}, {1.2, 0.45}, {1.1, 0.7}, {0.85, 0.6}}, 0.1);
  const Obstacle circle =
      Obstacle::makeCircle("c", ObstacleKind::kBollard, {{0.5, 0.5}, 0.03}, 0.1);
  for (const double theta_deg : {0.0, 30.0, -75.0, 180.0}) {
    const double theta = degToRad(theta_deg);
    const std::vector<Eigen::Vector2d> slice = cspaceSlice(polygon, robot, theta);
    int inside = 0;
    for (double x = 0.7; x <= 1.35; x += 0.005) {
      for (double y = 0.25; y <= 0.85; y += 0.005) {
        const double d = testing::exactSignedDistance(footprintAt(robot, {x, y, theta}), polygon);
        if (std::abs(d) < 1e-6) continue;
        EXPECT_EQ(insideConvex(slice, {x, y}), d < 0.0) << x << " " << y << " " << theta_deg;
        inside += d < 0.0;
      }
    }
    EXPECT_GT(inside, 100);
    const std::vector<Eigen::Vector2d> round = cspaceSlice(circle, robot, theta, 8);
    EXPECT_GE(round.size(), 32u);
    for (const Eigen::Vector2d& q : round) {
      EXPECT_NEAR(testing::exactSignedDistance(footprintAt(robot, {q.x(), q.y(), theta}), circle),
                  0.0, 1e-12);
    }
  }
}

}  // namespace
}  // namespace parksim
