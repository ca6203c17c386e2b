#pragma once
// Where a search looks: the box around the start and the goal, grown by a margin, within the
// lot. The problem sets the size of the grids and the cells, not the lot: a start and a goal
// metres apart in a lot of a kilometre search the same few square metres as in a small lot. A
// search that runs out of room (every reachable cell of the window expanded) tries again in a
// window twice as wide, up to the whole lot.

#include "parksim/core/geometry/Pose2.h"
#include "parksim/core/model/Scenario.h"

namespace parksim {

struct SearchWindowDef {
  double min_margin_m = 0.5;     ///< the window reaches at least this far beyond start and goal, m
  double margin_fraction = 0.5;  ///< and at least this fraction of their distance
};

/// The window for `a` and `b` in `lot` with margin `margin_m` on every side, clipped to the lot.
LotBounds searchWindow(const LotBounds& lot, const Pose2& a, const Pose2& b, double margin_m);

/// The first margin for `a` and `b`: the larger of def.min_margin_m and def.margin_fraction
/// times their distance, m.
double firstMargin(const SearchWindowDef& def, const Pose2& a, const Pose2& b);

/// True when `window` is the whole `lot`.
bool coversLot(const LotBounds& window, const LotBounds& lot);

}  // namespace parksim
