#include "parksim/planner/search/SearchCells.h"

#include <cmath>
#include <utility>

#include "parksim/core/geometry/Angle.h"

namespace parksim {

namespace {

std::int64_t cellsAlong(double length_m, double cell_m) {
  return static_cast<std::int64_t>(std::ceil(length_m / cell_m));
}

}  // namespace

SearchCells::SearchCells(const LotBounds& window, CellSize coarse, CellSize fine,
                         double fine_zone_m, std::vector<Pose2> sources)
    : x_min_m_(window.x_min_m),
      y_min_m_(window.y_min_m),
      width_m_(window.x_max_m - window.x_min_m),
      height_m_(window.y_max_m - window.y_min_m),
      coarse_(coarse),
      fine_(fine),
      fine_zone_m_(fine_zone_m),
      sources_(std::move(sources)) {
  coarse_cells_ = (cellsAlong(width_m_, coarse_.cell_m) + 1) *
                  (cellsAlong(height_m_, coarse_.cell_m) + 1) *
                  static_cast<std::int64_t>(coarse_.heading_bins);
}

bool SearchCells::inFineZone(const Pose2& p) const {
  if (!fine_on_) return false;
  for (const Pose2& q : sources_) {
    if (positionDistance(p, q) < fine_zone_m_) return true;
  }
  return false;
}

std::int64_t SearchCells::key(const Pose2& p) const {
  const bool fine = inFineZone(p);
  const CellSize& size = fine ? fine_ : coarse_;
  const double c = size.cell_m;
  const int bins = size.heading_bins;
  const std::int64_t nx = cellsAlong(width_m_, c) + 1;
  const std::int64_t ny = cellsAlong(height_m_, c) + 1;
  const auto i = static_cast<std::int64_t>(std::floor((p.x - x_min_m_) / c));
  const auto j = static_cast<std::int64_t>(std::floor((p.y - y_min_m_) / c));
  const double turns = wrapAngle(p.theta) / (2.0 * kPi) + 0.5;  // [0, 1]
  const auto k = static_cast<std::int64_t>(std::floor(turns * bins + 0.5)) % bins;
  return (fine ? coarse_cells_ : 0) + (k * ny + j) * nx + i;
}

}  // namespace parksim
