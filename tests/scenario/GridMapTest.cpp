// A grid map's cells as one compound obstacle: occupied and unknown cells, the inflation, the
// merged rectangles.

#include "parksim/scenario/maps/GridMap.h"

#include <random>

#include <gtest/gtest.h>

namespace parksim {
namespace {

TEST(GridMap, DilationMatchesABruteForceDistanceCheck) {
  std::mt19937_64 rng(4);
  for (const double radius : {0.5, 1.0, 1.5, 2.3, 4.0}) {
    const int w = 37;
    const int h = 23;
    std::bernoulli_distribution set(0.04);
    std::vector<std::uint8_t> cells(static_cast<std::size_t>(w * h));
    for (auto& c : cells) c = set(rng) ? 1 : 0;
    const std::vector<std::uint8_t> grown = dilateCells(cells, w, h, radius);
    for (int j = 0; j < h; ++j) {
      for (int i = 0; i < w; ++i) {
        bool near = false;
        for (int q = 0; q < h && !near; ++q) {
          for (int p = 0; p < w && !near; ++p) {
            near = cells[static_cast<std::size_t>(q * w + p)] &&
                   (p - i) * (p - i) + (q - j) * (q - j) <= radius * radius;
          }
        }
        ASSERT_EQ(grown[static_cast<std::size_t>(j * w + i)], near ? 1 : 0)
            << "radius " << radius << " cell " << i << "," << j;
      }
    }
  }
}

TEST(GridMap, OneCompoundObstacleCoveringExactlyTheBlockingCells) {
  auto grid = std::make_shared<OccupancyGrid>();
  grid->width = 4;
  grid->height = 3;
  grid->resolution_m = 0.5;
  grid->origin = {1.0, 0.0, 0.0};
  const auto o = static_cast<std::uint8_t>(MapCell::kOccupied);
  const auto u = static_cast<std::uint8_t>(MapCell::kUnknown);
  // Rows from the bottom: an occupied row, a free row with one unknown cell, a free row.
  grid->cells = {o, o, o, o, 0, 0, u, 0, 0, 0, 0, 0};
  GridMapDef def{"m", "m.yaml", ObstacleKind::kWall, 0.2, true, 0.0};
  const GridMapObstacles a = gridMapObstacles(grid, def);
  ASSERT_TRUE(a.obstacle);
  EXPECT_EQ(a.obstacle->shape, ObstacleShape::kCompound);
  EXPECT_EQ(a.parts, 2u);
  EXPECT_EQ(a.obstacle->box.center, Eigen::Vector2d(2.0, 0.5));
  EXPECT_EQ(a.obstacle->box.half_extents, Eigen::Vector2d(1.0, 0.5));
  EXPECT_EQ(*a.layer.occupied_cells, (std::vector<CellRect>{{0, 0, 4, 1}}));
  EXPECT_EQ(*a.layer.unknown_cells, (std::vector<CellRect>{{2, 1, 3, 2}}));
  def.unknown_blocks = false;
  EXPECT_EQ(gridMapObstacles(grid, def).parts, 1u);
  // Inflated by one cell: the row above the wall and the unknown cell's neighbours.
  def.unknown_blocks = true;
  def.inflation_m = 0.5;
  const GridMapObstacles grown = gridMapObstacles(grid, def);
  EXPECT_EQ(grown.obstacle->box.half_extents, Eigen::Vector2d(1.0, 0.75));
  // Occupied and unknown cells are drawn as the map says them, not inflated.
  EXPECT_EQ(*grown.layer.occupied_cells, (std::vector<CellRect>{{0, 0, 4, 1}}));
  // A map with nothing blocking has no obstacle but still its layer.
  std::fill(grid->cells.begin(), grid->cells.end(), 0);
  const GridMapObstacles empty = gridMapObstacles(grid, def);
  EXPECT_FALSE(empty.obstacle);
  EXPECT_EQ(empty.layer.grid, grid);
}

}  // namespace
}  // namespace parksim
