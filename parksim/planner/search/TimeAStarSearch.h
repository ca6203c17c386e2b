#pragma once
// Internal to TimeAStar: one weighted A* search in time over one window (TimeAStar.h explains
// the search), the differential drive's moves and costs in the loop every cell search runs
// (CellSearch.h).

#include <vector>

#include "parksim/core/geometry/Pose2.h"
#include "parksim/core/model/RobotDef.h"
#include "parksim/planner/motion/TimeOptimalTiming.h"
#include "parksim/planner/search/CellSearch.h"

namespace parksim {

struct TimeAStarDef;

namespace detail {

struct TimeSearchConfig : CellSearchConfig {
  RobotDef robot;
  const TimeAStarDef* def = nullptr;
  TimingLimits limits;  ///< prices the moves (TimeCost.h)
};

using TimeSearchOutcome = CellSearchOutcome;

/// Searches from `sources` toward `targets` (the goal roots toward the start when searching
/// from the goal, else the start toward the roots); the result is driven from `start` (the
/// start pose either way). Searching backwards, moves are driven the other way round.
TimeSearchOutcome runTimeSearch(const TimeSearchConfig& config, const std::vector<Pose2>& sources,
                                const std::vector<Pose2>& targets, bool backward);

}  // namespace detail
}  // namespace parksim
