// Compound obstacles (non-convex polygons, polygons with holes, a map's merged cells) in the
// collision world: Bullet's compound shape holds the parts, and the footprint queries agree
// with an independent point-in-polygon check (tests/support/PolygonOracle.h) on 10^5 random
// poses; clearance is the exact distance to the nearest part.

#include <BulletCollision/CollisionShapes/btCompoundShape.h>
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "parksim/collision/BulletCollisionWorld.h"
#include "parksim/collision/ObstacleShape.h"
#include "parksim/core/geometry/ConvexPartition.h"
#include "parksim/core/geometry/GridRectangles.h"
#include "parksim/core/model/Scenario.h"
#include "tests/support/PolygonOracle.h"
#include "tests/support/Sanitizers.h"

namespace parksim {
namespace {

using testing::Ring;

Scenario lotWith(Obstacle o) {
  Scenario s;
  s.lot = {-1.0, -1.0, 3.0, 3.0};
  s.obstacles.push_back(std::move(o));
  return s;
}

TEST(CompoundObstacle, IsABulletCompoundOfBoxesForRectanglesAndHullsOtherwise) {
  // An L as two rectangles (one turned, as a rotated map's are), and a triangle beside it.
  const double c = std::cos(0.3);
  const double sn = std::sin(0.3);
  const auto turned = [&](double x, double y) {
    return Eigen::Vector2d(c * x - sn * y, sn * x + c * y);
  };
  std::vector<Ring> parts{{{0, 0}, {2, 0}, {2, 1}, {0, 1}},
                          {turned(0, 1), turned(1, 1), turned(1, 2), turned(0, 2)},
                          {{3, 0}, {4, 0}, {3.5, 1}}};
  const Obstacle o =
      Obstacle::makeCompound("l", ObstacleKind::kWall, CompoundShape::make(parts, {}), 0.2);
  for (const ObstacleShapeDef& def : {kExactObstacleShapes, kContactObstacleShapes}) {
    const auto shape = makeObstacleShape(o, def);
    ASSERT_EQ(shape->getShapeType(), COMPOUND_SHAPE_PROXYTYPE);
    const auto& compound = static_cast<const btCompoundShape&>(*shape);
    ASSERT_EQ(compound.getNumChildShapes(), 3);
    EXPECT_EQ(compound.getChildShape(0)->getShapeType(), BOX_SHAPE_PROXYTYPE);
    EXPECT_EQ(compound.getChildShape(1)->getShapeType(), BOX_SHAPE_PROXYTYPE);
    EXPECT_EQ(compound.getChildShape(2)->getShapeType(), CONVEX_HULL_SHAPE_PROXYTYPE);
    // Each box child sits where its part is, relative to the obstacle's bounding-box centre.
    for (int k = 0; k < 2; ++k) {
      const btVector3 at = compound.getChildTransform(k).getOrigin();
      Eigen::Vector2d mean = Eigen::Vector2d::Zero();
      for (const Eigen::Vector2d& v : parts[static_cast<std::size_t>(k)]) mean += v / 4.0;
      EXPECT_NEAR(double(at.x()), mean.x() - o.box.center.x(), 1e-6);
      EXPECT_NEAR(double(at.y()), mean.y() - o.box.center.y(), 1e-6);
    }
  }
}

// The done-when check of issue 32 through Bullet: a star-shaped polygon with two holes.
TEST(CompoundObstacle, FootprintQueriesAgreeWithPointInPolygonOnOneHundredThousandPoses) {
  std::mt19937_64 rng(17);
  const PolygonWithHoles region = testing::starWithTwoHoles(rng, {1.0, 1.0}, 40);
  ASSERT_FALSE(regionProblem(region));
  const Scenario s = lotWith(Obstacle::makeCompound(
      "star", ObstacleKind::kIsland, CompoundShape::make(convexPartition(region), {}), 0.1));
  const BulletCollisionWorld world(s);
  const std::vector<Ring> rings{region.outer, region.holes[0], region.holes[1]};
  std::uniform_real_distribution<double> xy(-0.05, 2.05);
  std::uniform_real_distribution<double> yaw(-3.14159, 3.14159);
  int overlapping = 0;
  for (int k = 0; k < 100000; ++k) {
    const Pose2 pose{xy(rng), xy(rng), yaw(rng)};
    const bool oracle = testing::footprintOverlapsRings(footprintAt(s.robot, pose), rings);
    ASSERT_EQ(!world.isFree(pose), oracle) << "pose " << k;
    overlapping += oracle;
  }
  EXPECT_GT(overlapping, 20000);
  EXPECT_LT(overlapping, 80000);
}

TEST(CompoundObstacle, AMapsMergedCellsAnswerLikeTheCellsThemselves) {
  // A 60 x 40 grid of 2 cm cells, a fifth of them set; its rectangles as one obstacle.
  std::mt19937_64 rng(23);
  const int w = 60;
  const int h = 40;
  const double cell = 0.02;
  std::bernoulli_distribution set(0.2);
  std::vector<std::uint8_t> cells(static_cast<std::size_t>(w * h));
  for (auto& c : cells) c = set(rng) ? 1 : 0;
  std::vector<Ring> parts;
  for (const CellRect& r : mergeCells(cells, w, h)) {
    parts.push_back({{r.i0 * cell, r.j0 * cell},
                     {r.i1 * cell, r.j0 * cell},
                     {r.i1 * cell, r.j1 * cell},
                     {r.i0 * cell, r.j1 * cell}});
  }
  const Scenario s = lotWith(
      Obstacle::makeCompound("map", ObstacleKind::kWall, CompoundShape::make(parts, {}), 0.1));
  const BulletCollisionWorld world(s);
  std::uniform_real_distribution<double> x(-0.1, 1.3);
  std::uniform_real_distribution<double> y(-0.1, 0.9);
  std::uniform_real_distribution<double> yaw(-3.14159, 3.14159);
  int free = 0;
  // Each pose against every cell by hand: fewer under the sanitizers' tenfold cost.
  const int poses = testing::kSanitized ? 300 : 1000;
  for (int k = 0; k < poses; ++k) {
    const Pose2 pose{x(rng), y(rng), yaw(rng)};
    const OrientedBox fp = footprintAt(s.robot, pose);
    bool oracle = false;
    double nearest = std::numeric_limits<double>::infinity();
    for (int j = 0; j < h; ++j) {
      for (int i = 0; i < w; ++i) {
        if (!cells[static_cast<std::size_t>(j * w + i)]) continue;
        const Ring square{{i * cell, j * cell},
                          {(i + 1) * cell, j * cell},
                          {(i + 1) * cell, (j + 1) * cell},
                          {i * cell, (j + 1) * cell}};
        oracle = oracle || testing::footprintOverlapsRings(fp, {square});
        nearest = std::min(nearest, distance(fp, square));
      }
    }
    ASSERT_EQ(!world.isFree(pose), oracle) << "pose " << k;
    EXPECT_NEAR(world.clearance(pose), nearest, 1e-12) << "pose " << k;
    free += !oracle;
  }
  EXPECT_GT(free, poses / 10);  // poses off the map and in its gaps
}

}  // namespace
}  // namespace parksim
