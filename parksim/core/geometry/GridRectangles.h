#pragma once
// A grid's set cells as few rectangles, exactly: a map of a million cells becomes a few thousand
// parts for Bullet and the planner instead of a million. Rows first, then rectangles: each row's
// runs of set cells, each run grown upward through the rows above that hold exactly the same run
// (a wall's straight stretch, a shelf, a pillar become one rectangle each). Every set cell is
// covered once, no clear cell is covered, there are never more rectangles than runs, and the
// work is about one pass over the cells.

#include <cstdint>
#include <vector>

namespace parksim {

/// A rectangle of cells: columns [i0, i1) and rows [j0, j1).
struct CellRect {
  int i0 = 0;
  int j0 = 0;
  int i1 = 0;
  int j1 = 0;

  friend bool operator==(const CellRect&, const CellRect&) = default;
};

/// The set (non-zero) cells of a `width` x `height` grid, `cells[j * width + i]`, covered by
/// rectangles whose interiors are disjoint, in the order they were found.
std::vector<CellRect> mergeCells(const std::vector<std::uint8_t>& cells, int width, int height);

}  // namespace parksim
