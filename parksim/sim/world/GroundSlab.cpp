#include "parksim/sim/world/GroundSlab.h"

#include <algorithm>

namespace parksim {

namespace {

// One axis: [lo, hi] is the lot plus a metre; the reach replaces it where it is smaller.
void clip(double lo, double hi, double reach_lo, double reach_hi, double& half, double& centre) {
  if (reach_lo <= lo && reach_hi >= hi) return;  // the whole lot: as always
  lo = std::max(lo, reach_lo);
  hi = std::min(hi, reach_hi);
  half = 0.5 * (hi - lo);
  centre = 0.5 * (lo + hi);
}

}  // namespace

GroundSlab groundSlab(const LotBounds& lot, const std::optional<LotBounds>& reach,
                      double margin_m) {
  double half_x = 0.5 * (lot.x_max_m - lot.x_min_m) + 1.0;
  double half_y = 0.5 * (lot.y_max_m - lot.y_min_m) + 1.0;
  double cx = 0.5 * (lot.x_min_m + lot.x_max_m);
  double cy = 0.5 * (lot.y_min_m + lot.y_max_m);
  if (reach) {
    const double g = margin_m;
    clip(lot.x_min_m - 1.0, lot.x_max_m + 1.0, reach->x_min_m - g, reach->x_max_m + g, half_x, cx);
    clip(lot.y_min_m - 1.0, lot.y_max_m + 1.0, reach->y_min_m - g, reach->y_max_m + g, half_y, cy);
  }
  GroundSlab slab;
  slab.center = {cx, cy};
  slab.half_extents = {half_x, half_y};
  return slab;
}

}  // namespace parksim
