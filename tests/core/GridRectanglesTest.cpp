#include "parksim/core/geometry/GridRectangles.h"

#include <random>
#include <vector>

#include <gtest/gtest.h>

namespace parksim {
namespace {

TEST(GridRectangles, AFullGridIsOneRectangleAndAnEmptyOneNone) {
  EXPECT_EQ(mergeCells(std::vector<std::uint8_t>(12, 1), 4, 3),
            (std::vector<CellRect>{{0, 0, 4, 3}}));
  EXPECT_TRUE(mergeCells(std::vector<std::uint8_t>(12, 0), 4, 3).empty());
}

TEST(GridRectangles, AnLIsTwoRectangles) {
  // Row 0 (bottom) full, the left column up to the top.
  const std::vector<std::uint8_t> cells{1, 1, 1, 1, 0, 0, 1, 0, 0};
  EXPECT_EQ(mergeCells(cells, 3, 3), (std::vector<CellRect>{{0, 0, 3, 1}, {0, 1, 1, 3}}));
}

TEST(GridRectangles, RandomGridsAreCoveredExactlyOnceAndOnlyWhereSet) {
  std::mt19937_64 rng(11);
  for (const double density : {0.05, 0.3, 0.6, 0.9}) {
    for (int trial = 0; trial < 10; ++trial) {
      const int w = 1 + static_cast<int>(rng() % 120);
      const int h = 1 + static_cast<int>(rng() % 80);
      std::bernoulli_distribution set(density);
      std::vector<std::uint8_t> cells(static_cast<std::size_t>(w * h));
      int runs = 0;
      for (int j = 0; j < h; ++j) {
        for (int i = 0; i < w; ++i) {
          cells[static_cast<std::size_t>(j * w + i)] = set(rng) ? 1 : 0;
          runs += cells[static_cast<std::size_t>(j * w + i)] &&
                  (i == 0 || !cells[static_cast<std::size_t>(j * w + i - 1)]);
        }
      }
      const std::vector<CellRect> rects = mergeCells(cells, w, h);
      std::vector<int> cover(cells.size(), 0);
      for (const CellRect& r : rects) {
        ASSERT_LT(r.i0, r.i1);
        ASSERT_LT(r.j0, r.j1);
        for (int j = r.j0; j < r.j1; ++j) {
          for (int i = r.i0; i < r.i1; ++i) ++cover[static_cast<std::size_t>(j * w + i)];
        }
      }
      for (std::size_t k = 0; k < cells.size(); ++k) ASSERT_EQ(cover[k], cells[k] ? 1 : 0);
      // Never more rectangles than row runs: merging only joins.
      EXPECT_LE(static_cast<int>(rects.size()), runs);
    }
  }
}

TEST(GridRectangles, RefusesASizeThatDoesNotMatchTheCells) {
  EXPECT_THROW(mergeCells(std::vector<std::uint8_t>(5, 1), 2, 3), std::exception);
}

}  // namespace
}  // namespace parksim
