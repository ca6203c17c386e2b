#include "parksim/scenario/maps/GridMap.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace parksim {

namespace {

// One pass of the squared distance transform along a line of n values f (0 at set cells,
// infinity elsewhere): d[q] = min over p of (q - p)^2 + f[p], by the lower envelope of
// parabolas.
void distanceLine(const double* f, double* d, int n, std::vector<int>& v, std::vector<double>& z) {
  const double inf = std::numeric_limits<double>::infinity();
  v.assign(static_cast<std::size_t>(n), 0);
  z.assign(static_cast<std::size_t>(n) + 1, 0.0);
  int k = -1;
  for (int q = 0; q < n; ++q) {
    if (f[q] == inf) continue;
    if (k < 0) {
      k = 0;
      v[0] = q;
      z[0] = -inf;
      z[1] = inf;
      continue;
    }
    double s = 0.0;
    while (true) {
      const int p = v[static_cast<std::size_t>(k)];
      s = ((f[q] + double(q) * q) - (f[p] + double(p) * p)) / (2.0 * (q - p));
      if (s <= z[static_cast<std::size_t>(k)] && k > 0) {
        --k;
        continue;
      }
      break;
    }
    if (s <= z[static_cast<std::size_t>(k)]) {
      // k == 0 and the new parabola is lower everywhere: it replaces the first.
      v[0] = q;
      z[0] = -inf;
      z[1] = inf;
      continue;
    }
    ++k;
    v[static_cast<std::size_t>(k)] = q;
    z[static_cast<std::size_t>(k)] = s;
    z[static_cast<std::size_t>(k) + 1] = inf;
  }
  if (k < 0) {
    std::fill(d, d + n, inf);
    return;
  }
  int j = 0;
  for (int q = 0; q < n; ++q) {
    while (z[static_cast<std::size_t>(j) + 1] < q) ++j;
    const int p = v[static_cast<std::size_t>(j)];
    d[q] = double(q - p) * (q - p) + f[p];
  }
}

}  // namespace

std::vector<std::uint8_t> dilateCells(const std::vector<std::uint8_t>& cells, int width, int height,
                                      double radius_cells) {
  if (!(radius_cells > 0.0)) return cells;
  const double inf = std::numeric_limits<double>::infinity();
  const auto w = static_cast<std::size_t>(width);
  const auto h = static_cast<std::size_t>(height);
  std::vector<double> grid(cells.size());
  for (std::size_t k = 0; k < cells.size(); ++k) grid[k] = cells[k] ? 0.0 : inf;
  std::vector<double> f(std::max(w, h));
  std::vector<double> d(std::max(w, h));
  std::vector<int> v;
  std::vector<double> z;
  for (std::size_t i = 0; i < w; ++i) {  // columns
    for (std::size_t j = 0; j < h; ++j) f[j] = grid[j * w + i];
    distanceLine(f.data(), d.data(), height, v, z);
    for (std::size_t j = 0; j < h; ++j) grid[j * w + i] = d[j];
  }
  for (std::size_t j = 0; j < h; ++j) {  // rows
    distanceLine(grid.data() + j * w, d.data(), width, v, z);
    std::copy(d.begin(), d.begin() + static_cast<std::ptrdiff_t>(w),
              grid.begin() + static_cast<std::ptrdiff_t>(j * w));
  }
  const double r2 = radius_cells * radius_cells;
  std::vector<std::uint8_t> out(cells.size());
  for (std::size_t k = 0; k < cells.size(); ++k) out[k] = grid[k] <= r2 ? 1 : 0;
  return out;
}

GridMapObstacles gridMapObstacles(std::shared_ptr<const OccupancyGrid> grid,
                                  const GridMapDef& def) {
  const OccupancyGrid& g = *grid;
  const std::size_t n = g.cells.size();
  std::vector<std::uint8_t> occupied(n);
  std::vector<std::uint8_t> unknown(n);
  std::vector<std::uint8_t> blocks(n);
  for (std::size_t k = 0; k < n; ++k) {
    const auto c = static_cast<MapCell>(g.cells[k]);
    occupied[k] = c == MapCell::kOccupied;
    unknown[k] = c == MapCell::kUnknown;
    blocks[k] = occupied[k] || (def.unknown_blocks && unknown[k]);
  }
  blocks = dilateCells(blocks, g.width, g.height, def.inflation_m / g.resolution_m);
  GridMapObstacles out;
  out.layer.name = def.name;
  out.layer.source = def.source;
  out.layer.occupied_cells =
      std::make_shared<const std::vector<CellRect>>(mergeCells(occupied, g.width, g.height));
  out.layer.unknown_cells =
      std::make_shared<const std::vector<CellRect>>(mergeCells(unknown, g.width, g.height));
  const std::vector<CellRect> rects = mergeCells(blocks, g.width, g.height);
  out.parts = rects.size();
  if (!rects.empty()) {
    std::vector<std::vector<Eigen::Vector2d>> parts;
    parts.reserve(rects.size());
    for (const CellRect& r : rects) {
      const auto c = g.corners(r);
      parts.emplace_back(c.begin(), c.end());
    }
    out.obstacle = Obstacle::makeCompound(def.name, def.kind,
                                          CompoundShape::make(std::move(parts), {}), def.height_m);
  }
  out.layer.grid = std::move(grid);
  return out;
}

}  // namespace parksim
