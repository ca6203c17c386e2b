#include "parksim/core/Geometry.h"

#include <gtest/gtest.h>

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
