#include "parksim/renders/scene/DrawList.h"

#include <gtest/gtest.h>

namespace parksim {
namespace {

TEST(DrawListTest, GroundMarginsTileTheRestOfTheImage) {
  DrawList dl;
  dl.width_px = 50;
  dl.height_px = 40;
  for (const PixelRect& m : dl.groundMargins()) EXPECT_EQ(m, PixelRect{});  // no ground
  dl.ground = PixelRect{3, 5, 40, 30};
  std::vector<int> covered(50 * 40, 0);
  auto paint = [&](const PixelRect& r) {
    for (int y = r.y; y < r.y + r.height; ++y) {
      for (int x = r.x; x < r.x + r.width; ++x) ++covered[static_cast<std::size_t>(y * 50 + x)];
    }
  };
  paint(*dl.ground);
  for (const PixelRect& m : dl.groundMargins()) paint(m);
  for (int c : covered) EXPECT_EQ(c, 1);
}

TEST(DrawListTest, ClearEmptiesEveryBatch) {
  DrawList dl;
  dl.ground = PixelRect{0, 0, 1, 1};
  dl.mesh.resize(3);
  dl.mesh_blend.resize(6);
  dl.lines.resize(6);
  dl.lines_blend.resize(12);
  dl.text_boxes.resize(6);
  dl.glyphs.push_back({12, std::vector<OverlayVertex>(6)});
  EXPECT_EQ(dl.triangleCount(), 13u);
  dl.clear();
  EXPECT_FALSE(dl.ground.has_value());
  EXPECT_EQ(dl.triangleCount(), 0u);
  EXPECT_TRUE(dl.glyphs.empty());
}

}  // namespace
}  // namespace parksim
