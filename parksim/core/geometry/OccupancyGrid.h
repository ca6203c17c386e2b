#pragma once
// A map's cells as its file says them, placed in the lot: what a ROS map server's image or a
// Moving AI grid says of each cell (free, occupied, unknown) after the map's own rules
// (thresholds, negation, terrain letters). The world reader turns the cells into obstacles
// (merged rectangles, GridRectangles.h); the grid itself stays with the scenario so that figures
// can draw it under the lot and a user can see that the import is right.

#include <array>
#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "parksim/core/geometry/GridRectangles.h"
#include "parksim/core/geometry/Pose2.h"

namespace parksim {

/// What a map says of a cell.
enum class MapCell : std::uint8_t { kFree = 0, kOccupied = 1, kUnknown = 2 };

struct OccupancyGrid {
  int width = 0;               ///< cells along the map's x axis
  int height = 0;              ///< cells along the map's y axis
  double resolution_m = 0.05;  ///< side of a cell, m
  /// The outer corner of cell (0, 0) in the lot frame, and the map's x axis heading (rad,
  /// counter-clockwise): ROS's `origin`, the pose of the lower-left pixel's corner.
  Pose2 origin;
  /// width x height cells, row by row from the bottom (cell (i, j) at j * width + i): MapCell
  /// values.
  std::vector<std::uint8_t> cells;

  MapCell at(int i, int j) const {
    return static_cast<MapCell>(
        cells[static_cast<std::size_t>(j) * static_cast<std::size_t>(width) +
              static_cast<std::size_t>(i)]);
  }

  /// The lot-frame point at map coordinates (u, v) cells from the origin corner.
  Eigen::Vector2d toLot(double u, double v) const;

  /// The corners of a rectangle of cells in the lot frame, counter-clockwise from its
  /// lower-left corner (the map's axes).
  std::array<Eigen::Vector2d, 4> corners(const CellRect& rect) const;

  /// The map's whole rectangle, as corners().
  std::array<Eigen::Vector2d, 4> extent() const { return corners({0, 0, width, height}); }
};

}  // namespace parksim
