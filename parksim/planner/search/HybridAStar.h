#pragma once
// Hybrid A* (Dolgov, Thrun, Montemerlo, Diebel 2008) for the diff-drive robot: A* over
// (x, y, heading) cells whose nodes keep continuous poses, expanded by motion primitives
// (MotionPrimitives.h: arcs of the turning radius and straights, forward and reverse, and
// in-place turns). Cost: length, plus reverse_penalty per metre driven backwards, plus
// cusp_penalty_m per change of driving direction, plus in-place turns at the footprint radius
// per radian. Heuristic: the larger of the Reeds-Shepp length to the goal (no obstacles) and
// the grid distance around obstacles (ObstacleHeuristic.h). Analytic expansion: from expanded
// nodes (every node once the heuristic says the goal is near, otherwise every few), the exact
// Reeds-Shepp curve to the goal is tried; the first that validates ends the search.
//
// Every primitive and expansion is checked by the same gap-free MotionValidator as the tree
// planners, and the joined plan is validated once more as a whole; the plan is its exact pieces
// timed at the wheel limits (TimeOptimalTiming.h). Deterministic: no randomness at all, so the
// seed does not matter.

#include "parksim/core/model/RobotDef.h"
#include "parksim/core/model/Scenario.h"
#include "parksim/planner/base/PlanResult.h"
#include "parksim/planner/base/SearchDef.h"
#include "parksim/planner/motion/MotionValidator.h"
#include "parksim/planner/steering/ReedsSheppSteering.h"

namespace parksim {

struct HybridAStarDef {
  /// Side of the (x, y) cells, m; 0 selects the footprint radius / 4 (20 mm for the study's
  /// robot), grown for lots with more than 250 cells a side so the grid stays bounded.
  double cell_m = 0.0;
  int heading_bins = 72;  ///< heading cells (5 degrees each by default)
  /// Arc length of one primitive, m; 0 selects 1.5 cells, so a move leaves its cell.
  double step_m = 0.0;
  /// Arcs of this radius too, m (0: none). Below half the wheel base the inner wheel turns
  /// backwards: the robot pivots about a point between its wheels, which tight slots need.
  double tight_turning_radius_m = 0.02;
  /// Search from the goal back to the start and drive the path found the other way round
  /// (a diff-drive path reversed in time is a path). Parking goals are the tight end: growing
  /// the search from there finds the few ways out, and the analytic expansion then reaches the
  /// start across open space. Costs are those of the driven direction either way.
  bool from_goal = true;
  /// When the coarse search runs out of cells to expand (every reachable cell expanded: the
  /// poses it grows from are hemmed in), it starts again with a fine zone: near those poses
  /// (within fine_zone_m) cells, heading bins, steps and in-place turns are finer. A tight slot
  /// has only a few ways out, and coarse cells let the first pose that reaches a cell shut the
  /// others out. 0 disables the zone; a negative value selects twice the footprint radius.
  double fine_zone_m = -1.0;
  double fine_cell_m = 0.001;   ///< (x, y) cell side in the fine zone, m
  int fine_heading_bins = 360;  ///< heading cells in the fine zone (1 degree)
  double fine_step_m = 0.003;   ///< primitive arc length in the fine zone, m
  double fine_turn_in_place_rad = 2.0 * 3.14159265358979323846 / 180.0;
  /// In-place turn primitive, rad; 0 disables them.
  double turn_in_place_rad = 10.0 * 3.14159265358979323846 / 180.0;
  /// Analytic expansion is tried from every node whose heuristic is below this many steps, and
  /// from every analytic_interval-th expanded node otherwise.
  double analytic_near_steps = 10.0;
  int analytic_interval = 5;
  /// f = g + heuristic_weight * h; above 1 trades path cost for fewer expansions (>= 1).
  double heuristic_weight = 2.0;
};

class HybridAStar {
 public:
  /// `reeds_shepp` supplies the turning radius (of primitives and curves) and the analytic
  /// expansion; `def.max_iterations` bounds node expansions, `def.max_time_s` wall time.
  HybridAStar(const RobotDef& robot, const LotBounds& lot, const ReedsSheppSteering& reeds_shepp,
              const MotionValidator& validator, const SearchDef& def,
              const HybridAStarDef& hybrid = {});

  /// `progress`, when set, is told of every node expansion.
  PlanResult solve(const Pose2& start, const GoalRegion& goal,
                   const PlanProgress& progress = {}) const;

 private:
  RobotDef robot_;
  LotBounds lot_;
  const ReedsSheppSteering& reeds_shepp_;
  const MotionValidator& validator_;
  SearchDef def_;
  HybridAStarDef hybrid_;
};

}  // namespace parksim
