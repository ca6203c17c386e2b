#pragma once
// Hybrid A* in time ("time-a-star", parksim's default planner): the plan that minimises the
// duration of driving it, for a differential drive that can turn in place.
//
// The search (TimeAStarSearch.h) is A* over (x, y, heading) cells whose nodes keep continuous
// poses, grown from the goal (the tight end) by motion primitives: straight moves and arcs of
// several radii, forward and reverse, and turns in place by several angles. A move costs the
// time to drive it with the faster wheel at the wheel-speed limit less the feedback headroom,
// and each junction the time lost slowing down to change the wheels' ratio there at the
// acceleration limit (TimeCost.h): cusps and turns in place are priced by their stops. The
// heuristic is the larger of the Balkcom-Mason time to the start in free space (BalkcomMason.h)
// and the grid distance around obstacles at full speed (ObstacleHeuristic.h); the analytic
// expansion is the Balkcom-Mason path to the start, tried from every few expanded nodes; the
// first one that validates ends the search. The grids cover a window around the start and the
// goal (SearchWindow.h), so the problem, not the lot, sets their size.
//
// The path found is then smoothed (PathSmoother.h) and timed at the limits
// (TimeOptimalTiming.h). Anytime: with a wall-time budget (SearchDef::max_time_s) it searches
// again with smaller heuristic weights down to 1 (restarting weighted A*, Richter, Thayer and
// Ruml 2010) and smooths each new path with fresh random shortcuts, until the budget ends,
// keeping the fastest plan and recording every improvement in cost_history. Without one it makes
// one search and one smoothing: deterministic, the seed draws only the random shortcuts.
//
// PlanResult::cost is the plan's duration, s (objective kDuration).

#include <vector>

#include "parksim/core/model/RobotDef.h"
#include "parksim/core/model/Scenario.h"
#include "parksim/planner/base/PathSmoother.h"
#include "parksim/planner/base/PlanResult.h"
#include "parksim/planner/base/SearchDef.h"
#include "parksim/planner/motion/MotionValidator.h"
#include "parksim/planner/motion/TimeOptimalTiming.h"
#include "parksim/planner/search/SearchWindow.h"

namespace parksim {

struct TimeAStarDef {
  /// Side of the (x, y) cells, m; 0 selects the footprint radius / 4 (20 mm for the study's
  /// robot), whatever the size of the lot.
  double cell_m = 0.0;
  int heading_bins = 72;  ///< heading cells (5 degrees each by default)
  /// Length of one straight or arc move, m; 0 selects 1.5 cells, so a move leaves its cell.
  double step_m = 0.0;
  /// Arc radii of the moves, m (each > 0). Below half the wheel base the inner wheel turns
  /// backwards and the robot pivots about a point between its wheels, which tight slots need.
  std::vector<double> arc_radii_m{0.02, 0.08, 0.25};
  /// Turns in place, rad (each > 0), both ways.
  std::vector<double> spin_angles_rad{
      5.0 * 3.14159265358979323846 / 180.0, 15.0 * 3.14159265358979323846 / 180.0,
      45.0 * 3.14159265358979323846 / 180.0, 90.0 * 3.14159265358979323846 / 180.0};
  /// f = g + heuristic_weight * h for the first search (>= 1); anytime searches lower it by
  /// anytime_weight_step down to 1.
  double heuristic_weight = 3.0;
  double anytime_weight_step = 0.5;  ///< (> 0)
  /// The analytic expansion is tried from every node whose heuristic is below this, s, and from
  /// every analytic_interval-th expanded node otherwise.
  double analytic_near_s = 1.0;
  int analytic_interval = 4;
  /// Search from the goal back to the start (the path is then driven the other way round).
  bool from_goal = true;
  /// When the coarse search expands every reachable cell of its window, it starts again with a
  /// fine zone around the poses it grows from: finer cells, heading bins, moves and turns within
  /// fine_zone_m (a negative value selects twice the footprint radius; 0 disables the zone). If
  /// that runs dry too, once more with the zone's cells, moves and turns halved and its heading
  /// bins doubled.
  double fine_zone_m = -1.0;
  double fine_cell_m = 0.002;   ///< (x, y) cell side in the fine zone, m
  int fine_heading_bins = 180;  ///< heading cells in the fine zone (2 degrees)
  double fine_step_m = 0.004;   ///< straight and arc move length in the fine zone, m
  /// Turns in place in the fine zone, rad.
  std::vector<double> fine_spin_angles_rad{2.0 * 3.14159265358979323846 / 180.0,
                                           10.0 * 3.14159265358979323846 / 180.0};
  SearchWindowDef window;
  /// The obstacle heuristic's grid has at most this many cells along the window's longer side:
  /// its cells are the search cells, or larger on wide windows.
  int max_heuristic_cells_per_side = 250;
};

class TimeAStar {
 public:
  /// `limits` time the plan (the wheel-speed limit less the feedback headroom, the acceleration
  /// limit, the control period); `def.max_iterations` bounds node expansions per search,
  /// `def.max_time_s` the wall time (and makes the search anytime); `def.smooth` smooths with
  /// `smoothing`.
  /// `obstacles`, when given, make the heuristic's grid from their shapes (FootprintFit.h)
  /// rather than from footprint queries: the same answers at a tenth of the cost.
  TimeAStar(const RobotDef& robot, const LotBounds& lot, const MotionValidator& validator,
            const SearchDef& def, const TimeAStarDef& search, const TimingLimits& limits,
            const PathSmootherDef& smoothing = {},
            const std::vector<Obstacle>* obstacles = nullptr);

  /// The plan as timed at `limits`; cost and cost_history in seconds of duration.
  PlanResult solve(const Pose2& start, const GoalRegion& goal,
                   const PlanProgress& progress = {}) const;

 private:
  RobotDef robot_;
  LotBounds lot_;
  const MotionValidator& validator_;
  SearchDef def_;
  TimeAStarDef search_;
  TimingLimits limits_;
  PathSmootherDef smoothing_;
  const std::vector<Obstacle>* obstacles_;
};

}  // namespace parksim
