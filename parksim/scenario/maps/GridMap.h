#pragma once
// A grid map's cells as obstacles: the cells that block the robot (occupied ones, and unknown
// ones unless the world says otherwise), grown by the world's inflation, merged into rectangles
// (GridRectangles.h) that become the convex parts of one compound obstacle: one Bullet body per
// map, however many cells it has. Internal to the scenario module.

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "parksim/core/model/Scenario.h"

namespace parksim {

/// What a world asks of a grid map (its `map:` entry).
struct GridMapDef {
  std::string name;    ///< the obstacle's name
  std::string source;  ///< the map file, for MapLayer and messages
  ObstacleKind kind = ObstacleKind::kWall;
  double height_m = 0.1;
  bool unknown_blocks = true;  ///< unknown cells are obstacles
  /// Free cells whose centre lies within this distance of an obstacle cell's centre become
  /// obstacles too, m (>= 0): the costmap's inflation, on the grid.
  double inflation_m = 0.0;
};

/// The map's obstacle (none when no cell blocks) and its layer for drawing.
struct GridMapObstacles {
  std::optional<Obstacle> obstacle;
  MapLayer layer;
  std::size_t parts = 0;  ///< rectangles of the obstacle
};

GridMapObstacles gridMapObstacles(std::shared_ptr<const OccupancyGrid> grid, const GridMapDef& def);

/// Cells within `radius_cells` (centre to centre) of a set cell, set: an exact Euclidean
/// dilation by the squared distance transform (Felzenszwalb and Huttenlocher), linear in the
/// cells whatever the radius.
std::vector<std::uint8_t> dilateCells(const std::vector<std::uint8_t>& cells, int width, int height,
                                      double radius_cells);

}  // namespace parksim
