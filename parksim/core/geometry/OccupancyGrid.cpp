#include "parksim/core/geometry/OccupancyGrid.h"

#include <cmath>

namespace parksim {

Eigen::Vector2d OccupancyGrid::toLot(double u, double v) const {
  const double c = std::cos(origin.theta);
  const double s = std::sin(origin.theta);
  const double x = u * resolution_m;
  const double y = v * resolution_m;
  return {origin.x + c * x - s * y, origin.y + s * x + c * y};
}

std::array<Eigen::Vector2d, 4> OccupancyGrid::corners(const CellRect& r) const {
  return {toLot(r.i0, r.j0), toLot(r.i1, r.j0), toLot(r.i1, r.j1), toLot(r.i0, r.j1)};
}

}  // namespace parksim
