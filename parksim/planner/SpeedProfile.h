#pragma once
// Rest-to-rest speed profiles for piecewise-constant commands. A profile covers a given signed
// distance (metres of travel or radians of turn) exactly, so states integrated from it land on
// the target up to rounding, while it respects a speed limit and a per-period change limit.

#include <vector>

namespace parksim {

/// Speeds u_0..u_{N-1}, each held for one `period_s`, with sum(u_i) * period_s == distance (up
/// to rounding), |u_i| <= max_speed, |u_i - u_{i-1}| <= max_step, and |u_0|, |u_{N-1}| <=
/// max_step / 2. The half steps at both ends let a profile start from rest, stop, or follow
/// another such profile directly, each within one max_step. N is the smallest count for which
/// such a trapezoid reaches the distance; the trapezoid is then scaled down to hit it exactly.
/// Empty when distance is 0. Units: speeds in distance units per second, max_step per period.
std::vector<double> restToRestProfile(double distance, double max_speed, double max_step,
                                      double period_s);

}  // namespace parksim
