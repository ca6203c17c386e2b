#pragma once
// Internal to TimeAStar: one weighted A* search in time over one window (TimeAStar.h explains
// the search). Coarse first; when that expands every reachable cell of the window, once more
// with the fine zone around the poses it grows from, and once more with that zone twice as fine.

#include <atomic>
#include <chrono>
#include <vector>

#include "parksim/core/geometry/Pose2.h"
#include "parksim/core/model/RobotDef.h"
#include "parksim/core/model/Scenario.h"
#include "parksim/planner/base/PlanResult.h"
#include "parksim/planner/motion/MotionValidator.h"
#include "parksim/planner/motion/TimeOptimalTiming.h"

namespace parksim {

struct TimeAStarDef;
class FootprintFit;

namespace detail {

struct TimeSearchConfig {
  RobotDef robot;
  LotBounds window;  ///< nodes stay inside; the heuristic grid covers it
  const MotionValidator* validator = nullptr;
  /// The heuristic grid's free test; null: the validator's footprint queries (slower).
  const FootprintFit* fit = nullptr;
  const TimeAStarDef* def = nullptr;
  TimingLimits limits;  ///< prices the moves (TimeCost.h)
  double weight = 1.0;  ///< heuristic weight (>= 1)
  /// Poses the heuristic grid sees no way from are left out. The grid tests cell centres only,
  /// so a passage narrower than a cell may hide from it: a search that finds nothing with this
  /// tries again without.
  bool trust_grid = true;
  long max_expansions = 0;
  /// Wall-time end of the search; time_point::max() for none.
  std::chrono::steady_clock::time_point deadline = std::chrono::steady_clock::time_point::max();
  /// Stops the search like the deadline when set and true (SearchDef::cancel).
  const std::atomic<bool>* cancel = nullptr;
  const PlanProgress* progress = nullptr;
  long progress_offset = 0;  ///< expansions of earlier searches, for the progress display
  long progress_budget = 0;
};

struct TimeSearchOutcome {
  enum class Status {
    kFound,
    kExhausted,  ///< every reachable cell of the window was expanded
    kBudget,     ///< max_expansions reached
    kTimeLimit,
  };
  Status status = Status::kExhausted;
  /// Found: the path from `start` (the first source or target, see run) in driving order.
  std::vector<PathPiece> pieces;
  long expansions = 0;
  long nodes = 0;
  long analytic_attempts = 0;
  double heuristic_s = 0.0;  ///< building the obstacle heuristic's grid
  double analytic_s = 0.0;   ///< analytic expansions (steering and validating)
  double collision_s = 0.0;  ///< validating moves
};

/// Searches from `sources` toward `targets` (the goal roots toward the start when searching
/// from the goal, else the start toward the roots); the result is driven from `start` (the
/// start pose either way). Searching backwards, moves are driven the other way round.
TimeSearchOutcome runTimeSearch(const TimeSearchConfig& config, const std::vector<Pose2>& sources,
                                const std::vector<Pose2>& targets, bool backward);

}  // namespace detail
}  // namespace parksim
