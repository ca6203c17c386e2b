// The one policy by which obstacles become Bullet shapes (collision/ObstacleShape.h): the
// outer surface, margin included, is the obstacle's outline extruded to its height, for both
// margin choices; the margins are the documented ones.

#include "parksim/collision/ObstacleShape.h"

#include <BulletCollision/CollisionShapes/btBoxShape.h>
#include <BulletCollision/CollisionShapes/btConvexHullShape.h>
#include <BulletCollision/CollisionShapes/btCylinderShape.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "parksim/core/geometry/Angle.h"

namespace parksim {
namespace {

// Float rounding of lot-scale coordinates, m.
constexpr double kFloat_m = 1e-6;

const ObstacleShapeDef kBoth[] = {kExactObstacleShapes, kContactObstacleShapes};

// Farthest extent of the shape (margin included) along the planar unit direction `u`.
double support(const btCollisionShape& shape, const Eigen::Vector2d& u) {
  const auto& convex = static_cast<const btConvexShape&>(shape);
  const btVector3 dir(btScalar(u.x()), btScalar(u.y()), 0);
  const btVector3 p = convex.localGetSupportingVertex(dir);
  return double(p.x()) * u.x() + double(p.y()) * u.y();
}

double polygonSupport(const std::vector<Eigen::Vector2d>& polygon, const Eigen::Vector2d& centre,
                      const Eigen::Vector2d& u) {
  double best = -1e300;
  for (const Eigen::Vector2d& v : polygon) best = std::max(best, (v - centre).dot(u));
  return best;
}

TEST(ObstacleShape, BoxesAreTheirOutlineWithTheChosenMargin) {
  const Obstacle wall = Obstacle::makeBox("wall", ObstacleKind::kWall,
                                          OrientedBox{{0.9, 0.0}, {0.9, 0.01}, 0.0}, 0.1);
  for (const ObstacleShapeDef& def : kBoth) {
    const auto shape = makeObstacleShape(wall, def);
    ASSERT_EQ(shape->getShapeType(), BOX_SHAPE_PROXYTYPE);
    const btVector3 outer = static_cast<const btBoxShape&>(*shape).getHalfExtentsWithMargin();
    EXPECT_NEAR(outer.x(), 0.9, kFloat_m);
    EXPECT_NEAR(outer.y(), 0.01, kFloat_m);
    EXPECT_NEAR(outer.z(), 0.05, kFloat_m);
  }
  // Exact: no margin, half extents bit for bit as the float of the obstacle's.
  const auto exact = makeObstacleShape(wall, kExactObstacleShapes);
  EXPECT_EQ(exact->getMargin(), btScalar(0));
  const btVector3 half = static_cast<const btBoxShape&>(*exact).getHalfExtentsWithMargin();
  EXPECT_EQ(half.x(), btScalar(0.9));
  EXPECT_EQ(half.y(), btScalar(0.01));
  EXPECT_EQ(half.z(), btScalar(0.05));
  // Contact: Bullet's own margin, a tenth of the smallest half extent (at most 4 cm).
  EXPECT_NEAR(makeObstacleShape(wall, kContactObstacleShapes)->getMargin(), 0.001, kFloat_m);
  const Obstacle big =
      Obstacle::makeBox("block", ObstacleKind::kBox, OrientedBox{{0.0, 0.0}, {1.0, 1.0}, 0.0}, 2.0);
  EXPECT_NEAR(makeObstacleShape(big, kContactObstacleShapes)->getMargin(), 0.04, kFloat_m);
}

TEST(ObstacleShape, DiscsAreTheirOutlineWithTheChosenMargin) {
  for (const double radius : {0.0004, 0.025, 0.08}) {
    const Obstacle bollard =
        Obstacle::makeCircle("bollard", ObstacleKind::kBollard, {{0.4, 0.3}, radius}, 0.1);
    for (const ObstacleShapeDef& def : kBoth) {
      const auto shape = makeObstacleShape(bollard, def);
      ASSERT_EQ(shape->getShapeType(), CYLINDER_SHAPE_PROXYTYPE);
      EXPECT_NEAR(shape->getMargin(), std::min(def.margin_m, 0.5 * radius), 1e-9);
      for (int k = 0; k < 8; ++k) {
        const double a = 2.0 * kPi * k / 8;
        EXPECT_NEAR(support(*shape, {std::cos(a), std::sin(a)}), radius, kFloat_m);
      }
      btTransform identity;
      identity.setIdentity();
      btVector3 lo, hi;
      shape->getAabb(identity, lo, hi);
      EXPECT_NEAR(hi.z(), 0.05, kFloat_m);
      EXPECT_NEAR(lo.z(), -0.05, kFloat_m);
    }
  }
}

TEST(ObstacleShape, PolygonsAreTheirOutlineAlongEveryEdgeNormal) {
  const std::vector<Eigen::Vector2d> triangle{{0.9, 0.2}, {1.1, 0.25}, {0.95, 0.4}};
  const Obstacle island = Obstacle::makePolygon("island", ObstacleKind::kIsland, triangle, 0.05);
  for (const ObstacleShapeDef& def : kBoth) {
    const auto shape = makeObstacleShape(island, def);
    ASSERT_EQ(shape->getShapeType(), CONVEX_HULL_SHAPE_PROXYTYPE);
    EXPECT_NEAR(shape->getMargin(), def.margin_m, 1e-9);
    for (std::size_t i = 0; i < triangle.size(); ++i) {
      const Eigen::Vector2d e = (triangle[(i + 1) % 3] - triangle[i]).normalized();
      const Eigen::Vector2d normal(e.y(), -e.x());
      EXPECT_NEAR(support(*shape, normal), polygonSupport(triangle, island.box.center, normal),
                  kFloat_m);
    }
    // Between the normals the corners are rounded: the polygon moved in by the margin, grown
    // by a disc of the margin, inside the outline.
    const std::vector<Eigen::Vector2d> core =
        def.margin_m > 0.0 ? insetPolygon(triangle, def.margin_m) : triangle;
    for (int k = 0; k < 36; ++k) {
      const double a = 2.0 * kPi * k / 36;
      const Eigen::Vector2d u(std::cos(a), std::sin(a));
      EXPECT_NEAR(support(*shape, u), polygonSupport(core, island.box.center, u) + def.margin_m,
                  kFloat_m);
      EXPECT_LE(support(*shape, u), polygonSupport(triangle, island.box.center, u) + kFloat_m);
    }
  }
}

TEST(ObstacleShape, APolygonsMarginIsCappedByItsSize) {
  const std::vector<Eigen::Vector2d> sliver{{1.4, 0.6}, {1.7, 0.6}, {1.7, 0.6008}, {1.4, 0.6008}};
  const Obstacle o = Obstacle::makePolygon("sliver", ObstacleKind::kCurb, sliver, 0.05);
  // A quarter of the smaller half extent (0.4 mm): 0.1 mm, not 0.5 mm.
  EXPECT_NEAR(makeObstacleShape(o, kContactObstacleShapes)->getMargin(), 0.0001, 1e-9);
}

TEST(ObstacleShape, InsetPolygonMovesEveryEdgeInwardByTheDistance) {
  const std::vector<Eigen::Vector2d> square{{0, 0}, {2, 0}, {2, 2}, {0, 2}};
  const std::vector<Eigen::Vector2d> inset = insetPolygon(square, 0.1);
  ASSERT_EQ(inset.size(), 4u);
  EXPECT_TRUE(inset[0].isApprox(Eigen::Vector2d(0.1, 0.1)));
  EXPECT_TRUE(inset[2].isApprox(Eigen::Vector2d(1.9, 1.9)));
  // A skewed triangle: each inset edge lies on the line of its edge moved in by d.
  const std::vector<Eigen::Vector2d> tri{{0, 0}, {1, 0.1}, {0.2, 0.7}};
  const double d = 0.01;
  const std::vector<Eigen::Vector2d> in = insetPolygon(tri, d);
  for (std::size_t i = 0; i < 3; ++i) {
    const Eigen::Vector2d e = (tri[(i + 1) % 3] - tri[i]).normalized();
    const Eigen::Vector2d outward(e.y(), -e.x());
    EXPECT_NEAR((tri[i] - in[i]).dot(outward), d, 1e-12);
    EXPECT_NEAR((tri[(i + 1) % 3] - in[(i + 1) % 3]).dot(outward), d, 1e-12);
  }
  // Zero distance: the polygon itself, bit for bit.
  EXPECT_EQ(insetPolygon(tri, 0.0), tri);
}

}  // namespace
}  // namespace parksim
