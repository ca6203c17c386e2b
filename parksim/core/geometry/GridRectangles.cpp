#include "parksim/core/geometry/GridRectangles.h"

#include <cstddef>
#include <string>

#include "parksim/core/io/Error.h"

namespace parksim {

std::vector<CellRect> mergeCells(const std::vector<std::uint8_t>& cells, int width, int height) {
  if (width < 0 || height < 0 ||
      cells.size() != static_cast<std::size_t>(width) * static_cast<std::size_t>(height)) {
    throw Error("merge cells: the grid holds " + std::to_string(cells.size()) +
                " cells, not width x height");
  }
  const auto w = static_cast<std::size_t>(width);
  const auto set = [&](int i, int j) {
    return cells[static_cast<std::size_t>(j) * w + static_cast<std::size_t>(i)] != 0;
  };
  // Row j holds exactly the run [i0, i1): set there, clear (or the edge) on either side.
  const auto sameRun = [&](int j, int i0, int i1) {
    if ((i0 > 0 && set(i0 - 1, j)) || (i1 < width && set(i1, j))) return false;
    for (int i = i0; i < i1; ++i) {
      if (!set(i, j)) return false;
    }
    return true;
  };
  std::vector<std::uint8_t> absorbed(cells.size(), 0);  // the first cell of a run merged below
  std::vector<CellRect> out;
  for (int j = 0; j < height; ++j) {
    for (int i = 0; i < width;) {
      if (!set(i, j)) {
        ++i;
        continue;
      }
      int i1 = i + 1;
      while (i1 < width && set(i1, j)) ++i1;
      if (absorbed[static_cast<std::size_t>(j) * w + static_cast<std::size_t>(i)] == 0) {
        int j1 = j + 1;
        while (j1 < height && sameRun(j1, i, i1)) {
          absorbed[static_cast<std::size_t>(j1) * w + static_cast<std::size_t>(i)] = 1;
          ++j1;
        }
        out.push_back({i, j, i1, j1});
      }
      i = i1;
    }
  }
  return out;
}

}  // namespace parksim
