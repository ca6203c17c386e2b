#pragma once
// Rest-to-rest speed profiles for piecewise-constant commands. A profile covers a given signed
// distance (metres of travel or radians of turn) exactly, so states integrated from it land on
// the target up to rounding, while it respects a speed limit and a per-period change limit.

#include <vector>

namespace parksim {

/// Most periods one profile may take (docs/limits.md): 10^5 periods are 10^4 s at the planner's
/// 0.1 s period, far beyond any lot's longest move at the robot's limits, and ~5 MB of rows.
inline constexpr double kMaxProfilePeriods = 100'000;

/// About how many periods restToRestProfile needs (within a few), computed in O(1) without
/// building the profile, so limits can be checked first. May be huge; never overflows.
double restToRestPeriods(double distance, double max_speed, double max_step, double period_s);

/// Speeds u_0..u_{N-1}, each held for one `period_s`, with sum(u_i) * period_s == distance (up
/// to rounding), |u_i| <= max_speed, |u_i - u_{i-1}| <= max_step, and |u_0|, |u_{N-1}| <=
/// max_step / 2. The half steps at both ends let a profile start from rest, stop, or follow
/// another such profile directly, each within one max_step. N is the smallest count for which
/// such a trapezoid reaches the distance; the trapezoid is then scaled down to hit it exactly.
/// Empty when distance is 0. Units: speeds in distance units per second, max_step per period.
/// Throws Error when N would exceed kMaxProfilePeriods. Work and memory are O(N).
std::vector<double> restToRestProfile(double distance, double max_speed, double max_step,
                                      double period_s);

}  // namespace parksim
