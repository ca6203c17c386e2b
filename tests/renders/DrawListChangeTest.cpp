#include "parksim/renders/scene/DrawListChange.h"

#include <gtest/gtest.h>

#include <random>
#include <vector>

namespace parksim {
namespace {

// A 200x100 list whose overlay triangles are given in pixels (x right, y down from the top-left
// corner), as the renderer will place them.
class DrawListChangeTest : public ::testing::Test {
 protected:
  DrawListChangeTest() {
    list_.width_px = 200;
    list_.height_px = 100;
  }
  // Clip space as the overlay shader takes it: y up (the shader flips it).
  static OverlayVertex at(float x_px, float y_px) {
    OverlayVertex v{};
    v.pos[0] = x_px / 100.0f - 1.0f;
    v.pos[1] = 1.0f - y_px / 50.0f;
    v.pos[3] = 1.0f;
    v.color[3] = 255;
    return v;
  }
  static void addTriangle(std::vector<OverlayVertex>& batch, float x, float y, float size = 4.0f) {
    batch.push_back(at(x, y));
    batch.push_back(at(x + size, y));
    batch.push_back(at(x, y + size));
  }
  static bool inside(const PixelRect& outer, float x0, float y0, float x1, float y1) {
    return outer.x <= x0 && outer.y <= y0 && x1 <= outer.x + outer.width &&
           y1 <= outer.y + outer.height;
  }
  DrawList list_;
};

TEST_F(DrawListChangeTest, EqualListsChangeNothing) {
  for (int i = 0; i < 50; ++i) addTriangle(list_.lines, 3.0f * i, 1.5f * i);
  list_.glyphs.push_back({12, {}});
  addTriangle(list_.glyphs.back().vertices, 10, 10);
  EXPECT_TRUE(changedRects(list_, list_).empty());
  EXPECT_TRUE(changedRects(DrawList{}, DrawList{}).empty());
}

TEST_F(DrawListChangeTest, AMovedTriangleChangesItsOldAndNewPlaceOnly) {
  for (int i = 0; i < 20; ++i) addTriangle(list_.lines, 8.0f * i, 40.0f);
  DrawList after = list_;
  after.lines[30].pos[0] += 0.5f;  // triangle 10, from x = 80 to x = 130 px
  after.lines[31].pos[0] += 0.5f;
  after.lines[32].pos[0] += 0.5f;
  const std::vector<PixelRect> rects = changedRects(list_, after);
  ASSERT_EQ(rects.size(), 2u);
  long long pixels = 0;
  bool old_place = false, new_place = false;
  for (const PixelRect& r : rects) {
    old_place |= inside(r, 80, 40, 84, 44);
    new_place |= inside(r, 130, 40, 134, 44);
    pixels += static_cast<long long>(r.width) * r.height;
  }
  EXPECT_TRUE(old_place);
  EXPECT_TRUE(new_place);
  EXPECT_LE(pixels, 2 * 10 * 10) << "4 px triangles, 2 px margins, rounded out";
}

// A driven path grows at its end while the planned path it is drawn after loses its start: the
// triangles between are the same, found by looking ahead, and cost nothing.
TEST_F(DrawListChangeTest, TrianglesDroppedAndAddedLeaveTheRestUnchanged) {
  for (int i = 0; i < 40; ++i) addTriangle(list_.lines_blend, 4.0f * i, 20.0f + i);
  DrawList after = list_;
  after.lines_blend.erase(after.lines_blend.begin(), after.lines_blend.begin() + 6);  // 2 fewer
  addTriangle(after.lines_blend, 170, 80);
  addTriangle(after.lines_blend, 175, 82);
  const std::vector<PixelRect> rects = changedRects(list_, after);
  ASSERT_FALSE(rects.empty());
  for (const PixelRect& r : rects) {
    EXPECT_LE(r.width, 20) << "only the path's ends";
    EXPECT_LE(r.height, 20);
  }
  bool start = false, end = false;
  for (const PixelRect& r : rects) {
    start |= inside(r, 0, 20, 8, 25);
    end |= inside(r, 170, 80, 179, 86);
  }
  EXPECT_TRUE(start);
  EXPECT_TRUE(end);
}

TEST_F(DrawListChangeTest, ANewCameraOrLightChangesEverything) {
  addTriangle(list_.lines, 10, 10);
  const std::vector<PixelRect> all = {{0, 0, 200, 100}};
  DrawList moved = list_;
  moved.view_proj(0, 3) = 0.1f;
  EXPECT_EQ(changedRects(list_, moved), all);
  DrawList lit = list_;
  lit.ambient = 0.5f;
  EXPECT_EQ(changedRects(list_, lit), all);
  DrawList bigger = list_;
  bigger.width_px = 201;
  EXPECT_EQ(changedRects(list_, bigger), (std::vector<PixelRect>{{0, 0, 201, 100}}));
}

// A perspective camera can put a changed vertex behind it: where the clipped triangle lands is
// not worked out, the whole image counts.
TEST_F(DrawListChangeTest, AChangedVertexBehindTheCameraChangesEverything) {
  list_.view_proj.setZero();
  list_.view_proj(0, 0) = list_.view_proj(1, 1) = list_.view_proj(2, 2) = 1.0f;
  list_.view_proj(3, 2) = 1.0f;  // w = z: in front for z > 0
  MeshVertex v{};
  v.pos[2] = 1.0f;
  list_.mesh.assign(3, v);
  DrawList after = list_;
  after.mesh[1].pos[2] = -0.5f;
  EXPECT_EQ(changedRects(list_, after), (std::vector<PixelRect>{{0, 0, 200, 100}}));
  after.mesh[1].pos[2] = 2.0f;  // in front: only its own place
  const std::vector<PixelRect> near = changedRects(list_, after);
  ASSERT_EQ(near.size(), 1u);
  EXPECT_LT(near[0].width * near[0].height, 200 * 100);
}

TEST_F(DrawListChangeTest, AGlyphSizeOnlyOneListHasChangesItsGlyphs) {
  list_.glyphs.push_back({12, {}});
  addTriangle(list_.glyphs.back().vertices, 10, 10);
  DrawList after = list_;
  after.glyphs.push_back({20, {}});
  addTriangle(after.glyphs.back().vertices, 150, 60);
  const std::vector<PixelRect> rects = changedRects(list_, after);
  ASSERT_EQ(rects.size(), 1u);
  EXPECT_TRUE(inside(rects[0], 150, 60, 154, 64));
  EXPECT_FALSE(inside(rects[0], 10, 10, 14, 14));
  EXPECT_EQ(changedRects(after, list_), rects) << "and the other way round";
}

// However scattered the change, the rectangles are few and cover every changed triangle.
TEST_F(DrawListChangeTest, ScatteredChangesStayFewAndCovered) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> x(0.0f, 190.0f), y(0.0f, 90.0f);
  for (int i = 0; i < 300; ++i) addTriangle(list_.lines, x(rng), y(rng), 3.0f);
  DrawList after = list_;
  std::vector<int> moved;
  for (int t = 0; t < 300; t += 7) {
    moved.push_back(t);
    for (int k = 0; k < 3; ++k) after.lines[static_cast<std::size_t>(3 * t + k)].pos[1] -= 0.02f;
  }
  for (int max_rects : {1, 4, 9}) {
    DrawListChangeDef def;
    def.max_rects = max_rects;
    const std::vector<PixelRect> rects = changedRects(list_, after, def);
    ASSERT_FALSE(rects.empty());
    EXPECT_LE(static_cast<int>(rects.size()), max_rects);
    for (int t : moved) {
      for (const DrawList* l : {&list_, &after}) {
        const OverlayVertex& v = l->lines[static_cast<std::size_t>(3 * t)];
        const float px = (v.pos[0] + 1.0f) * 100.0f;
        const float py = (1.0f - v.pos[1]) * 50.0f;
        bool covered = false;
        for (const PixelRect& r : rects) covered |= inside(r, px, py, px + 3.0f, py + 3.0f);
        EXPECT_TRUE(covered) << "triangle " << t << " with max_rects " << max_rects;
      }
    }
  }
}

// Settings out of range are held to their bounds: no hang, no list without end.
TEST_F(DrawListChangeTest, SettingsAreBounded) {
  for (int i = 0; i < 200; ++i) addTriangle(list_.lines, (i * 37) % 190, (i * 53) % 90, 3.0f);
  DrawList after = list_;
  for (OverlayVertex& v : after.lines) v.pos[0] += 0.001f;  // every triangle moved
  DrawListChangeDef wild;
  wild.max_rects = 1 << 30;
  wild.lookahead = 1 << 30;
  wild.margin_px = 1 << 30;
  const std::vector<PixelRect> rects = changedRects(list_, after, wild);
  ASSERT_FALSE(rects.empty());
  EXPECT_LE(rects.size(), 64u);
  for (const PixelRect& r : rects) {
    EXPECT_GE(r.x, 0);
    EXPECT_LE(r.x + r.width, 200);
  }
  wild.max_rects = -5;
  EXPECT_EQ(changedRects(list_, after, wild).size(), 1u);
}

TEST_F(DrawListChangeTest, RectanglesStayOnTheImage) {
  addTriangle(list_.lines, -50, -50, 60);  // reaches in from above the top-left corner
  DrawList after = list_;
  addTriangle(after.lines, 1e9f, 1e9f);  // far off the image: no rectangle
  after.lines[0].pos[0] += 0.01f;
  const std::vector<PixelRect> rects = changedRects(list_, after);
  ASSERT_EQ(rects.size(), 1u);
  EXPECT_EQ(rects[0].x, 0);
  EXPECT_EQ(rects[0].y, 0);
  EXPECT_LE(rects[0].x + rects[0].width, 200);
  EXPECT_LE(rects[0].y + rects[0].height, 100);
}

}  // namespace
}  // namespace parksim
