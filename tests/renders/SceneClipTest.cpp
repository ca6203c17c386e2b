#include "parksim/renders/scene/SceneClip.h"

#include <gtest/gtest.h>

#include <cmath>

#include "parksim/core/geometry/Angle.h"

namespace parksim {
namespace {

const Extent2 kArea{0.0, 0.0, 1.0, 0.6};

double polygonArea(const std::vector<Eigen::Vector2d>& p) {
  double twice = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Eigen::Vector2d& a = p[i];
    const Eigen::Vector2d& b = p[(i + 1) % p.size()];
    twice += a.x() * b.y() - b.x() * a.y();
  }
  return 0.5 * twice;
}

bool inArea(const Eigen::Vector2d& p, const Extent2& a = kArea) {
  return p.x() >= a.x_min && p.x() <= a.x_max && p.y() >= a.y_min && p.y() <= a.y_max;
}

TEST(SceneClipTest, PolygonInsideIsUnchangedAndOutsideVanishes) {
  const std::vector<Eigen::Vector2d> inside = {{0.1, 0.1}, {0.3, 0.1}, {0.2, 0.4}};
  EXPECT_EQ(clipPolygon(inside, kArea), inside);
  EXPECT_TRUE(clipPolygon({{1.1, 0.1}, {1.3, 0.1}, {1.2, 0.4}}, kArea).empty());
  // Touching the area along its border from outside leaves no area: dropped.
  EXPECT_TRUE(clipPolygon({{0.2, -0.1}, {0.4, -0.1}, {0.4, 0.0}, {0.2, 0.0}}, kArea).empty());
  // The lot's own surface, exactly the area, stays.
  const std::vector<Eigen::Vector2d> lot = {{0.0, 0.0}, {1.0, 0.0}, {1.0, 0.6}, {0.0, 0.6}};
  EXPECT_EQ(clipPolygon(lot, kArea), lot);
}

TEST(SceneClipTest, PolygonAcrossACornerKeepsExactlyItsInsidePart) {
  // A square centred on the area's top-right corner: a quarter of it lies inside.
  const std::vector<Eigen::Vector2d> square = {{0.9, 0.5}, {1.1, 0.5}, {1.1, 0.7}, {0.9, 0.7}};
  const std::vector<Eigen::Vector2d> clipped = clipPolygon(square, kArea);
  ASSERT_EQ(clipped.size(), 4u);
  EXPECT_NEAR(polygonArea(clipped), 0.25 * polygonArea(square), 1e-15);
  for (const Eigen::Vector2d& p : clipped) EXPECT_TRUE(inArea(p)) << p.transpose();
  // Clockwise input stays clockwise.
  const std::vector<Eigen::Vector2d> cw(square.rbegin(), square.rend());
  EXPECT_NEAR(polygonArea(clipPolygon(cw, kArea)), -0.01, 1e-15);
}

TEST(SceneClipTest, PolylineIsSplitWherePartsLieOutside) {
  // In, out across the top, back in, then out to the right and in again along the same line.
  ScenePolyline line{{{0.2, 0.3, 0.001}, {0.2, 0.9, 0.003}, {0.4, 0.3, 0.005}, {1.4, 0.3, 0.005}},
                     rgb(1, 2, 3),
                     2.5f,
                     false};
  const std::vector<ScenePolyline> pieces = clipPolyline(line, kArea);
  ASSERT_EQ(pieces.size(), 2u);
  EXPECT_EQ(pieces[0].points.size(), 2u);
  EXPECT_TRUE(pieces[0].points[0].isApprox(Eigen::Vector3d(0.2, 0.3, 0.001)));
  // The crossing of the top border is half way along the first segment: z interpolated too.
  EXPECT_TRUE(pieces[0].points[1].isApprox(Eigen::Vector3d(0.2, 0.6, 0.002)));
  ASSERT_EQ(pieces[1].points.size(), 3u);  // in at the top, down to (0.4, 0.3), out at x = 1
  EXPECT_NEAR(pieces[1].points[0].y(), 0.6, 1e-15);
  EXPECT_TRUE(pieces[1].points[2].isApprox(Eigen::Vector3d(1.0, 0.3, 0.005)));
  EXPECT_TRUE(clipPolyline({{{2.0, 0.3, 0.0}}, {}, 1.0f, false}, kArea).empty());
  EXPECT_EQ(clipPolyline({{}, {}, 1.0f, false}, kArea).size(), 1u);  // nothing to cut
  for (const ScenePolyline& piece : pieces) {
    EXPECT_FALSE(piece.closed);
    EXPECT_EQ(piece.color, line.color);
    EXPECT_EQ(piece.width_px, line.width_px);
  }
}

TEST(SceneClipTest, BorderLinesStayAndClosedLinesJoinAcrossTheirStart) {
  // The lot's border outline lies on the bounds: inclusive, so it stays whole and closed.
  const ScenePolyline border{
      {{0.0, 0.0, 0.0}, {1.0, 0.0, 0.0}, {1.0, 0.6, 0.0}, {0.0, 0.6, 0.0}}, {}, 1.0f, true};
  const std::vector<ScenePolyline> kept = clipPolyline(border, kArea);
  ASSERT_EQ(kept.size(), 1u);
  EXPECT_TRUE(kept[0].closed);
  EXPECT_EQ(kept[0].points, border.points);
  // A closed outline with one corner outside: one open piece, through the first point.
  const ScenePolyline outline{
      {{0.5, 0.3, 0.0}, {0.9, 0.3, 0.0}, {1.2, 0.5, 0.0}, {0.5, 0.5, 0.0}}, {}, 1.0f, true};
  const std::vector<ScenePolyline> pieces = clipPolyline(outline, kArea);
  ASSERT_EQ(pieces.size(), 1u);
  EXPECT_FALSE(pieces[0].closed);
  ASSERT_EQ(pieces[0].points.size(), 5u);
  EXPECT_NEAR(pieces[0].points.front().x(), 1.0, 1e-15);
  EXPECT_NEAR(pieces[0].points.back().x(), 1.0, 1e-15);
  EXPECT_EQ(pieces[0].points[2], outline.points[0]);
}

TEST(SceneClipTest, BoxesInsideStayBoxesStraddlingOnesBecomePrismsOutsideOnesGo) {
  Scene scene;
  const SceneBox inside{OrientedBox{{0.5, 0.3}, {0.05, 0.02}, 0.3}, 0.0, 0.1, rgb(9, 9, 9)};
  const SceneBox straddling{OrientedBox{{1.0, 0.3}, {0.1, 0.05}, degToRad(20.0)}, 0.01, 0.2,
                            rgb(7, 8, 9)};
  const SceneBox outside{OrientedBox{{-0.3, 0.3}, {0.1, 0.1}, 0.0}, 0.0, 0.1, rgb(1, 1, 1)};
  scene.boxes = {inside, straddling, outside};
  clipToArea(scene, kArea);
  ASSERT_EQ(scene.boxes.size(), 1u);
  EXPECT_EQ(scene.boxes[0].footprint.center, inside.footprint.center);
  ASSERT_EQ(scene.prisms.size(), 1u);
  const ScenePrism& p = scene.prisms[0];
  EXPECT_EQ(p.z_min_m, 0.01);
  EXPECT_EQ(p.height_m, 0.2);
  EXPECT_EQ(p.color, straddling.color);
  for (const Eigen::Vector2d& q : p.footprint) EXPECT_TRUE(inArea(q)) << q.transpose();
  // The box is centred on the border x = 1: half of it lies inside, counter-clockwise.
  EXPECT_NEAR(polygonArea(p.footprint), 0.5 * 0.2 * 0.1, 1e-15);
}

TEST(SceneClipTest, ArrowsAreShortenedOrDroppedAndLabelsFollowTheirAnchor) {
  Scene scene;
  scene.arrows.push_back({{0.5, 0.04, -kPi / 2}, 0.1, 0.03, 0.0, rgb(0, 0, 0), 3.0f});  // tip out
  scene.arrows.push_back({{0.5, 0.3, 0.0}, 0.1, 0.03, 0.0, rgb(0, 0, 0), 3.0f});        // inside
  scene.arrows.push_back({{-0.1, 0.3, 0.0}, 0.3, 0.03, 0.0, rgb(0, 0, 0), 3.0f});       // tail out
  scene.texts.push_back(SceneText::worldLabel("in", {0.5, 0.6, 0.0}, 10.0f, rgb(0, 0, 0),
                                              HAlign::kLeft, VAlign::kTop));
  scene.texts.push_back(SceneText::worldLabel("out", {0.5, 0.61, 0.0}, 10.0f, rgb(0, 0, 0),
                                              HAlign::kLeft, VAlign::kTop));
  scene.texts.push_back(
      {"screen", std::nullopt, {-5.0, -5.0}, 10.0f, {}, {}, HAlign::kLeft, VAlign::kTop});
  clipToArea(scene, kArea);
  ASSERT_EQ(scene.arrows.size(), 2u);
  EXPECT_NEAR(scene.arrows[0].length_m, 0.04, 1e-15);  // ends on the border y = 0
  EXPECT_NEAR(scene.arrows[0].head_m, 0.012, 1e-15);   // in proportion
  EXPECT_EQ(scene.arrows[1].length_m, 0.1);
  ASSERT_EQ(scene.texts.size(), 2u);
  EXPECT_EQ(scene.texts[0].text, "in");
  EXPECT_EQ(scene.texts[1].text, "screen");
}

}  // namespace
}  // namespace parksim
