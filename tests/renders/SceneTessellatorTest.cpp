#include "parksim/renders/scene/SceneTessellator.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "parksim/renders/text/FontLookup.h"

namespace parksim {
namespace {

// A 1 x 1 m extent seen from above in a 200 x 200 image: 196 pixels per metre (fill 0.98), the
// extent's corner (0, 1) at pixel (2, 2).
Scene emptyScene() {
  Scene s;
  s.extent = {0.0, 0.0, 1.0, 1.0};
  return s;
}

Camera topCamera(const Scene& s, int w = 200, int h = 200) {
  return makeCamera(CameraDef{}, s, w, h);
}

Camera perspectiveCamera(const Scene& s) {
  CameraDef def;
  def.mode = CameraMode::kPerspective;
  return makeCamera(def, s, 200, 200);
}

// Pixel position of an overlay vertex (clip space to the image, y down).
Eigen::Vector2d pixel(const OverlayVertex& v, const DrawList& dl) {
  return {(v.pos[0] / v.pos[3] + 1.0) * 0.5 * dl.width_px,
          (1.0 - v.pos[1] / v.pos[3]) * 0.5 * dl.height_px};
}

class SceneTessellatorTest : public ::testing::Test {
 protected:
  DrawList tessellate(const Scene& scene, const Camera& cam, int samples = 1) {
    TessellationDef def;
    def.samples = samples;
    DrawList dl;
    tessellator_.tessellate(scene, cam, def, fonts_, dl);
    return dl;
  }

  SceneTessellator tessellator_;
  FontCache fonts_;  // no font
};

TEST_F(SceneTessellatorTest, BoxIsTopAndFourSidesWithOutwardNormals) {
  Scene s = emptyScene();
  s.boxes.push_back({OrientedBox{{0.5, 0.5}, {0.1, 0.05}, 0.0}, 0.02, 0.1, rgb(10, 20, 30)});
  const DrawList dl = tessellate(s, perspectiveCamera(s));
  ASSERT_EQ(dl.mesh.size(), 30u);  // 2 top + 8 side triangles, no bottom
  EXPECT_TRUE(dl.mesh_blend.empty());
  for (const MeshVertex& v : dl.mesh) {
    EXPECT_EQ(v.color[0], 10);
    EXPECT_EQ(v.color[3], 255);
    EXPECT_TRUE(v.pos[2] == 0.02f || v.pos[2] == static_cast<float>(0.02 + 0.1));
    // Every normal is a unit vector pointing away from the box's centre.
    const Eigen::Vector3f n(v.normal[0], v.normal[1], v.normal[2]);
    EXPECT_NEAR(n.norm(), 1.0f, 1e-6f);
    const Eigen::Vector3f out(v.pos[0] - 0.5f, v.pos[1] - 0.5f, n.z() > 0.5f ? 1.0f : 0.0f);
    EXPECT_GT(n.dot(out), 0.0f);
  }
  EXPECT_EQ(dl.triangleCount(), 10u);
}

TEST_F(SceneTessellatorTest, TranslucentGeometryGoesToTheBlendBatches) {
  Scene s = emptyScene();
  s.polygons.push_back({{{0.1, 0.1}, {0.4, 0.2}, {0.3, 0.5}}, 0.01, Rgba8{200, 60, 60, 80}});
  s.prisms.push_back({{{0.6, 0.6}, {0.8, 0.6}, {0.8, 0.8}, {0.7, 0.9}, {0.6, 0.8}},
                      0.0,
                      0.05,
                      Rgba8{1, 2, 3, 128}});
  s.lines.push_back({{{0.1, 0.1, 0.0}, {0.9, 0.1, 0.0}}, Rgba8{0, 0, 0, 100}, 2.0f, false});
  const DrawList dl = tessellate(s, topCamera(s), 4);
  EXPECT_TRUE(dl.mesh.empty());
  // Polygon: 1 triangle; prism: 3 on top, 2 per side.
  EXPECT_EQ(dl.mesh_blend.size(), 3u * (1 + 3 + 2 * 5));
  EXPECT_TRUE(dl.lines.empty());
  EXPECT_EQ(dl.lines_blend.size(), 6u);
}

TEST_F(SceneTessellatorTest, LineRibbonKeepsItsWidthInPixels) {
  Scene s = emptyScene();
  // A diagonal line: with multisampling the ribbon is exactly the line's width, solid.
  s.lines.push_back({{{0.2, 0.2, 0.0}, {0.8, 0.8, 0.0}}, rgb(0, 0, 255), 4.0f, false});
  const Camera cam = topCamera(s);
  DrawList dl = tessellate(s, cam, 4);
  ASSERT_EQ(dl.lines.size(), 6u);
  EXPECT_TRUE(dl.lines_blend.empty());
  const Eigen::Vector2d a = pixel(dl.lines[0], dl);  // tail, one side
  const Eigen::Vector2d b = pixel(dl.lines[1], dl);  // tail, other side
  EXPECT_NEAR((a - b).norm(), 4.0, 1e-4);
  // Square caps: the ribbon starts half a width before the tail.
  const Eigen::Vector2d tail = *cam.project({0.2, 0.2, 0.0});
  EXPECT_NEAR((0.5 * (a + b) - tail).norm(), 2.0, 1e-4);
  EXPECT_EQ(dl.lines[0].uv[1], kSolidHalfWidth);

  // Without multisampling it grows by half a pixel a side and fades: blended, half width in v.
  dl = tessellate(s, cam, 1);
  ASSERT_EQ(dl.lines_blend.size(), 6u);
  EXPECT_NEAR((pixel(dl.lines_blend[0], dl) - pixel(dl.lines_blend[1], dl)).norm(), 5.0, 1e-4);
  EXPECT_FLOAT_EQ(dl.lines_blend[0].uv[1], 2.0f);
  EXPECT_FLOAT_EQ(dl.lines_blend[0].uv[0], 2.5f);
  EXPECT_FLOAT_EQ(dl.lines_blend[1].uv[0], -2.5f);
}

TEST_F(SceneTessellatorTest, AxisAlignedLinesAreSolidWithoutMultisampling) {
  Scene s = emptyScene();
  s.lines.push_back({{{0.1, 0.5, 0.0}, {0.9, 0.5, 0.0}}, rgb(0, 0, 0), 1.0f, false});
  const DrawList dl = tessellate(s, topCamera(s), 1);
  EXPECT_EQ(dl.lines.size(), 6u);
  EXPECT_TRUE(dl.lines_blend.empty());
}

TEST_F(SceneTessellatorTest, DensePolylinesAreThinnedOnScreen) {
  Scene s = emptyScene();
  ScenePolyline line{{}, rgb(0, 0, 0), 2.0f, false};
  // 101 points 0.277 px apart on screen (196 px/m along a diagonal): points closer than 3 px
  // (1.5 widths) to the last one kept are dropped, the first and last always kept. Every 11th
  // is kept (3.05 px), 0..99, and the last: 10 segments instead of 100.
  for (int i = 0; i <= 100; ++i) line.points.emplace_back(0.4 + 0.001 * i, 0.4 + 0.001 * i, 0.0);
  s.lines.push_back(line);
  const DrawList dl = tessellate(s, topCamera(s), 4);
  EXPECT_EQ(dl.lines.size(), 10u * 6u);
  // The last segment ends at the last point (its far cap centred half a width beyond).
  const Eigen::Vector2d end = *topCamera(s).project(line.points.back());
  const Eigen::Vector2d far =
      0.5 * (pixel(dl.lines[dl.lines.size() - 2], dl) + pixel(dl.lines[dl.lines.size() - 1], dl));
  EXPECT_NEAR((far - end).norm(), 1.0, 1e-3);
}

TEST_F(SceneTessellatorTest, ClosedPolylineJoinsItsEnds) {
  Scene s = emptyScene();
  s.lines.push_back(boxOutline(OrientedBox{{0.5, 0.5}, {0.2, 0.2}, 0.3}, 0.0, rgb(0, 0, 0), 1.0f));
  const DrawList dl = tessellate(s, topCamera(s), 4);
  EXPECT_EQ(dl.lines.size(), 4u * 6u);
}

TEST_F(SceneTessellatorTest, SegmentsBehindAPerspectiveCameraAreClipped) {
  Scene s = emptyScene();
  const Camera cam = perspectiveCamera(s);
  const Eigen::Vector3d forward = (cam.view.block<1, 3>(2, 0).transpose()) * -1.0;  // view dir
  const Eigen::Vector3d behind1 = cam.eye - 0.5 * forward;
  const Eigen::Vector3d behind2 = cam.eye - 0.7 * forward + Eigen::Vector3d(0.1, 0.0, 0.0);
  s.lines.push_back({{behind1, behind2}, rgb(0, 0, 0), 2.0f, false});
  EXPECT_TRUE(tessellate(s, cam, 4).lines.empty());
  // One end in front: the segment is cut at the near plane, not dropped.
  s.lines[0].points[1] = {0.5, 0.5, 0.0};
  const DrawList dl = tessellate(s, cam, 4);
  EXPECT_EQ(dl.lines.size() + dl.lines_blend.size(), 6u);
  for (const OverlayVertex& v : dl.lines) EXPECT_GT(v.pos[3], 0.0f);
}

TEST_F(SceneTessellatorTest, TopViewsOutlineOpaqueFacesWithoutMultisampling) {
  Scene s = emptyScene();
  // Rotated: four slanted edges to smooth. Axis-aligned edges need none.
  s.boxes.push_back({OrientedBox{{0.3, 0.3}, {0.1, 0.1}, 0.5}, 0.0, 0.1, rgb(1, 2, 3)});
  s.boxes.push_back({OrientedBox{{0.7, 0.7}, {0.1, 0.1}, 0.0}, 0.0, 0.1, rgb(1, 2, 3)});
  s.boxes.push_back({OrientedBox{{0.7, 0.3}, {0.1, 0.1}, 0.5}, 0.0, 0.1, Rgba8{1, 2, 3, 100}});
  DrawList dl = tessellate(s, topCamera(s), 1);
  ASSERT_EQ(dl.lines_blend.size(), 4u * 6u);
  for (const OverlayVertex& v : dl.lines_blend) {
    EXPECT_EQ(v.color[2], 3);
    EXPECT_FLOAT_EQ(v.uv[1], 0.5f);  // a one-pixel line, fading
  }
  EXPECT_TRUE(tessellate(s, topCamera(s), 4).lines_blend.empty());
  EXPECT_TRUE(tessellate(s, perspectiveCamera(s), 1).lines_blend.empty());
}

TEST_F(SceneTessellatorTest, ArrowIsAShaftAndAHead) {
  Scene s = emptyScene();
  s.arrows.push_back({Pose2{0.2, 0.5, 0.0}, 0.3, 0.05, 0.0, rgb(200, 0, 0), 3.0f});
  const Camera cam = topCamera(s);
  const DrawList dl = tessellate(s, cam, 4);
  ASSERT_EQ(dl.lines.size(), 6u);            // the shaft, axis-aligned: solid
  ASSERT_EQ(dl.mesh.size(), 3u);             // the head
  EXPECT_FLOAT_EQ(dl.mesh[0].pos[0], 0.5f);  // the tip first
  EXPECT_FLOAT_EQ(dl.mesh[1].pos[0], 0.45f);
  EXPECT_FLOAT_EQ(dl.mesh[1].pos[1], 0.525f);
  // The shaft ends where the head begins, plus its square cap.
  const double base_px = cam.project({0.45, 0.5, 0.0})->x();
  EXPECT_NEAR(pixel(dl.lines[2], dl).x(), base_px + 1.5, 1e-3);
}

TEST_F(SceneTessellatorTest, GroundRectangleBecomesAClear) {
  Scene s = emptyScene();
  s.background = rgb(9, 9, 9);
  s.polygons.push_back({{{0.0, 0.0}, {1.0, 0.0}, {1.0, 1.0}, {0.0, 1.0}}, 0.0, rgb(7, 7, 7)});
  s.polygons.push_back({{{0.1, 0.1}, {0.2, 0.1}, {0.2, 0.2}}, 0.001, rgb(5, 5, 5)});
  const Camera cam = topCamera(s);
  DrawList dl = tessellate(s, cam, 4);
  ASSERT_TRUE(dl.ground.has_value());
  EXPECT_EQ(*dl.ground, (PixelRect{2, 2, 196, 196}));
  EXPECT_EQ(dl.clear_color, rgb(7, 7, 7));
  EXPECT_EQ(dl.background, rgb(9, 9, 9));
  EXPECT_EQ(dl.mesh.size(), 3u);  // only the triangle: the ground is not drawn
  int margin_pixels = 0;
  for (const PixelRect& m : dl.groundMargins()) {
    if (m.width > 0 && m.height > 0) margin_pixels += m.width * m.height;
  }
  EXPECT_EQ(margin_pixels, 200 * 200 - 196 * 196);

  // Seen in perspective, or rotated, the ground is drawn like any polygon.
  dl = tessellate(s, perspectiveCamera(s), 4);
  EXPECT_FALSE(dl.ground.has_value());
  EXPECT_EQ(dl.clear_color, rgb(9, 9, 9));
  EXPECT_EQ(dl.mesh.size(), 9u);
  s.polygons[0].points = {{0.5, 0.0}, {1.0, 0.5}, {0.5, 1.0}, {0.0, 0.5}};
  EXPECT_FALSE(tessellate(s, cam, 4).ground.has_value());
}

TEST_F(SceneTessellatorTest, GroundRectangleCoversThePixelsWhoseCentresLieInside) {
  Scene s = emptyScene();
  // Edges at fractional pixels: 0.123 m -> pixel 26.1, 0.877 m -> 173.9.
  s.polygons.push_back(
      {{{0.123, 0.2}, {0.877, 0.2}, {0.877, 0.6}, {0.123, 0.6}}, 0.0, rgb(7, 7, 7)});
  const Camera cam = makeCamera(CameraDef{}, s, 211, 157);
  const std::optional<PixelRect> r = groundRectangle(s, cam);
  ASSERT_TRUE(r.has_value());
  const Eigen::Vector2d a = *cam.project({0.123, 0.6, 0.0});
  const Eigen::Vector2d b = *cam.project({0.877, 0.2, 0.0});
  for (int i = 0; i < cam.width_px; ++i) {
    const bool inside = i + 0.5 >= a.x() && i + 0.5 < b.x();
    EXPECT_EQ(inside, i >= r->x && i < r->x + r->width) << "column " << i;
  }
  for (int j = 0; j < cam.height_px; ++j) {
    const bool inside = j + 0.5 >= a.y() && j + 0.5 < b.y();
    EXPECT_EQ(inside, j >= r->y && j < r->y + r->height) << "row " << j;
  }
}

TEST_F(SceneTessellatorTest, UniformsFollowTheCamera) {
  Scene s = emptyScene();
  DrawList dl = tessellate(s, topCamera(s));
  EXPECT_FALSE(dl.lit);
  Eigen::Matrix4f flip = Eigen::Matrix4f::Identity();
  flip(1, 1) = -1.0f;
  EXPECT_EQ(dl.view_proj, flip * topCamera(s).viewProjection().cast<float>());
  TessellationDef def;
  def.light_direction = {0.0, 0.0, 2.0};
  def.ambient = 0.3;
  tessellator_.tessellate(s, perspectiveCamera(s), def, fonts_, dl);
  EXPECT_TRUE(dl.lit);
  EXPECT_FLOAT_EQ(dl.light[2], 1.0f);
  EXPECT_FLOAT_EQ(dl.ambient, 0.3f);
  EXPECT_FLOAT_EQ(dl.up_factor, 1.0f);  // straight overhead: an upward face gets it all
}

TEST_F(SceneTessellatorTest, ReusingAListGivesTheSameGeometry) {
  Scene s = emptyScene();
  s.boxes.push_back({OrientedBox{{0.3, 0.3}, {0.1, 0.1}, 0.5}, 0.0, 0.1, rgb(1, 2, 3)});
  s.lines.push_back({{{0.1, 0.1, 0.0}, {0.5, 0.9, 0.0}}, rgb(0, 0, 0), 2.0f, false});
  const DrawList first = tessellate(s, topCamera(s));
  DrawList again;
  Scene other = emptyScene();
  other.lines.push_back({{{0.9, 0.1, 0.0}, {0.5, 0.2, 0.0}}, rgb(0, 0, 0), 7.0f, false});
  tessellator_.tessellate(other, topCamera(other), {}, fonts_, again);
  tessellator_.tessellate(s, topCamera(s), {}, fonts_, again);
  ASSERT_EQ(again.mesh.size(), first.mesh.size());
  ASSERT_EQ(again.lines_blend.size(), first.lines_blend.size());
  for (std::size_t i = 0; i < first.lines_blend.size(); ++i) {
    EXPECT_EQ(std::memcmp(&again.lines_blend[i], &first.lines_blend[i], sizeof(OverlayVertex)), 0);
  }
}

TEST_F(SceneTessellatorTest, TextWithoutAFontIsLeftOut) {
  Scene s = emptyScene();
  s.texts.push_back({"hello", std::nullopt, {10.0, 10.0}, 16.0f, rgb(0, 0, 0)});
  const DrawList dl = tessellate(s, topCamera(s));
  EXPECT_TRUE(dl.glyphs.empty());
  EXPECT_TRUE(dl.text_boxes.empty());
}

TEST(SceneTessellatorTextTest, TextIsGlyphQuadsBatchedBySize) {
  FontCache fonts(readFontFile(findFontFile()));
  Scene s = emptyScene();
  SceneText big{"ab", std::nullopt, {10.0, 20.0}, 24.2f, rgb(1, 1, 1)};
  big.background = Rgba8{255, 255, 255, 200};
  s.texts.push_back(big);
  s.texts.push_back({"a b", std::nullopt, {10.0, 60.0}, 12.0f, rgb(2, 2, 2)});
  s.texts.push_back(SceneText::worldLabel("c", {0.5, 0.5, 0.0}, 12.0f, rgb(3, 3, 3),
                                          HAlign::kCenter, VAlign::kMiddle));
  SceneTessellator tessellator;
  DrawList dl;
  tessellator.tessellate(s, topCamera(s), {}, fonts, dl);
  ASSERT_EQ(dl.glyphs.size(), 2u);
  EXPECT_EQ(dl.glyphs[0].font_px, 12);  // smallest first
  EXPECT_EQ(dl.glyphs[1].font_px, 24);
  EXPECT_EQ(dl.glyphs[0].vertices.size(), 3u * 6u);  // 'a', 'b' and 'c'; the space has none
  EXPECT_EQ(dl.glyphs[1].vertices.size(), 2u * 6u);
  EXPECT_EQ(dl.text_boxes.size(), 6u);
  // The world label is centred on its point.
  const FontAtlas& atlas = fonts.atlas(12);
  const Eigen::Vector2d centre = *topCamera(s).project({0.5, 0.5, 0.0});
  double x0 = 1e9, x1 = -1e9;
  for (std::size_t i = 12; i < 18; ++i) {
    const Eigen::Vector2d p = pixel(dl.glyphs[0].vertices[i], dl);
    x0 = std::min(x0, p.x());
    x1 = std::max(x1, p.x());
  }
  EXPECT_NEAR(0.5 * (x0 + x1), centre.x(), 0.5 * atlas.advance("c"));
  for (const OverlayVertex& v : dl.glyphs[1].vertices) EXPECT_EQ(v.color[0], 1);
}

}  // namespace
}  // namespace parksim
