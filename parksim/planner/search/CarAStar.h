#pragma once
// Hybrid A* for a car ("car-a-star", the default planner of a car; docs/planning.md, "Cars"):
// the path a car drives fastest, with the moves a car has.
//
// A* over (x, y, heading) cells whose nodes keep continuous poses, grown from the goal (the
// tight end) by moves a car can make: arcs of a few curvatures up to its tightest,
// tan(max_steer) / axle (RobotDef::maxCurvature), and straight moves, forward and reverse; it
// never turns in place. A move costs the time to drive it at the fastest speed its curvature
// allows, and each junction what it loses (CarTimeCost.h): passing a clothoid where the
// curvature changes, or stopping to change gear and steering standing, plus a penalty per gear
// change. The heuristic is the larger of the Reeds-Shepp length to the start at the car's
// tightest radius (no obstacles) and the grid distance around obstacles (ObstacleHeuristic.h,
// FootprintFit.h), both at the speed limit; the analytic expansion is the Reeds-Shepp curve to
// the start, tried from every few expanded nodes and every node near it; the first that
// validates ends the search. The grids cover a window around the start and the goal
// (SearchWindow.h), widened when the search runs out of room; where the coarse search runs
// dry, it searches again with finer cells and moves near the goal (a tight slot's few ways
// out).
//
// The result is a path of constant-curvature pieces (timed for validation only); the planner
// (CarAStarPlanner.cpp) smooths it and makes it a car's plan (PlanFinishing.h, CarPlanAlong.h).
// Deterministic: no randomness in the search.

#include <vector>

#include "parksim/core/model/RobotDef.h"
#include "parksim/core/model/Scenario.h"
#include "parksim/planner/base/PlanResult.h"
#include "parksim/planner/base/SearchDef.h"
#include "parksim/planner/motion/CarTiming.h"
#include "parksim/planner/motion/MotionValidator.h"
#include "parksim/planner/motion/TimeOptimalTiming.h"
#include "parksim/planner/search/SearchWindow.h"

namespace parksim {

struct CarAStarDef {
  /// Side of the (x, y) cells, m; 0 selects the footprint radius / 8 (0.48 m for the mid-size
  /// car).
  double cell_m = 0.0;
  int heading_bins = 72;  ///< heading cells (5 degrees each by default)
  /// Arc length of a move, m; 0 selects 1.5 cells, so a move leaves its cell.
  double step_m = 0.0;
  /// The moves' curvatures besides straight: this many evenly spaced up to the tightest, each
  /// way (2: half and full lock).
  int curvature_steps = 2;
  /// f = g + heuristic_weight * h (>= 1).
  double heuristic_weight = 1.2;
  /// Cost of a gear change on top of its stop and its steering, s (nav2's change penalty).
  double gear_change_penalty_s = 1.0;
  /// The analytic expansion is tried from every node whose heuristic is below this, s, and from
  /// every analytic_interval-th expanded node otherwise.
  double analytic_near_s = 4.0;
  int analytic_interval = 4;
  /// Search from the goal back to the start (the path is then driven the other way round).
  bool from_goal = true;
  /// When the coarse search expands every reachable cell of its window, it starts again with
  /// cells and moves fine_scale times as large (heading bins 1 / fine_scale times as many)
  /// within fine_zone_m of the poses it grows from (< 0: twice the footprint radius; 0: never).
  double fine_zone_m = -1.0;
  double fine_scale = 0.25;
  SearchWindowDef window{5.0, 0.5};
  /// Side of the obstacle heuristic's grid cells, m; 0 selects twice the search cells (the
  /// grid's free test asks the footprint in eight headings per cell: the grid is most of a short
  /// search's time). At most max_heuristic_cells_per_side along the window's longer side.
  double heuristic_cell_m = 0.0;
  int max_heuristic_cells_per_side = 250;
};

class CarAStar {
 public:
  /// `car` must be a car (RobotDef::isCar); `limits` price the moves (CarTimeCost.h);
  /// `def.max_iterations` bounds node expansions, `def.max_time_s` the wall time. `obstacles`,
  /// when given, make the heuristic's grid from their shapes (FootprintFit.h).
  CarAStar(const RobotDef& car, const LotBounds& lot, const MotionValidator& validator,
           const SearchDef& def, const CarAStarDef& search, const CarLimits& limits,
           const std::vector<Obstacle>* obstacles = nullptr);

  /// The path found, as pieces timed at the wheels' limits (for validation; a car's plan is
  /// made of them later), and the search's statistics.
  PlanResult solve(const Pose2& start, const GoalRegion& goal,
                   const PlanProgress& progress = {}) const;

 private:
  RobotDef car_;
  LotBounds lot_;
  const MotionValidator& validator_;
  SearchDef def_;
  CarAStarDef search_;
  CarLimits limits_;
  const std::vector<Obstacle>* obstacles_;
};

}  // namespace parksim
