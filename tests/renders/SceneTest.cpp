#include "parksim/renders/scene/Scene.h"

#include <gtest/gtest.h>

namespace parksim {
namespace {

double length(const ScenePolyline& l) {
  double s = 0.0;
  for (std::size_t i = 1; i < l.points.size(); ++i) s += (l.points[i] - l.points[i - 1]).norm();
  return s;
}

TEST(SceneTest, DashesKeepTheirLengthAroundCorners) {
  ScenePolyline line{{{0, 0, 0}, {0.1, 0, 0}, {0.1, 0.1, 0}}, rgb(1, 2, 3), 2.0f, false};
  const std::vector<ScenePolyline> dashes = dashed(line, 0.03, 0.01);
  // 0.2 m of line in periods of 0.04 m: five dashes of 0.03 m.
  ASSERT_EQ(dashes.size(), 5u);
  for (const ScenePolyline& d : dashes) EXPECT_NEAR(length(d), 0.03, 1e-12);
  EXPECT_EQ(dashes[2].points.size(), 3u);  // 0.08..0.10, around the corner, on to 0.11
  EXPECT_NEAR(dashes[2].points[1].x(), 0.1, 1e-15);
  for (const ScenePolyline& d : dashes) EXPECT_EQ(d.color, line.color);
}

TEST(SceneTest, ClosedOutlineIsDashedAllAround) {
  const ScenePolyline outline =
      boxOutline(OrientedBox{{0, 0}, {0.05, 0.05}, 0.0}, 0.0, rgb(0, 0, 0), 1.0f);
  EXPECT_TRUE(outline.closed);
  ASSERT_EQ(outline.points.size(), 4u);
  double total = 0.0;
  for (const ScenePolyline& d : dashed(outline, 0.01, 0.01)) total += length(d);
  EXPECT_NEAR(total, 0.2, 1e-12);  // half of the 0.4 m perimeter
}

TEST(SceneTest, DegenerateDashesReturnTheLine) {
  ScenePolyline line{{{0, 0, 0}, {1, 0, 0}}, rgb(0, 0, 0), 1.0f, false};
  EXPECT_EQ(dashed(line, 0.0, 0.1).size(), 1u);
  EXPECT_EQ(dashed(line, 0.1, 0.0).size(), 1u);
}

}  // namespace
}  // namespace parksim
