#pragma once
// One sampling-based tree planner; the variants are options of its loop, not copies.
//
// The start tree grows from the start; the goal side is a goal tree whose roots are the goal
// pose (and the goal pose turned by pi when the goal accepts either heading). Each iteration
// samples, extends a tree, and tries to connect the new node to the other side:
// - kRrt (study 2(e)): the start tree grows with fixed-horizon steering; a new node within
//   connect_radius_m of a goal root (SE(2) metric) tries a to-goal trajectory to it.
// - kRrtGoalConnect (study 2(f)): every new node tries a to-goal trajectory.
// - kRrtConnect: the goal tree grows too, on alternate iterations. Its edges run forward in
//   time from the new (child) node to its parent, toward the goal: each is steered from the
//   child, never a start-tree trajectory played backwards. New nodes of either tree try to
//   connect to the nearest node of the other.
// - kRrtStar: start-tree nodes are rest poses joined by rest-to-rest edges steered in kExact
//   mode, so the tree can be rewired: a new node picks the cheapest valid parent among its
//   neighbours, then becomes the parent of neighbours it reaches more cheaply. The cost is path
//   length plus penalties for reversing and cusps (PathCost.h). Anytime: it keeps improving
//   until max_iterations (or max_time_s) and records each improvement in cost_history. With
//   informed_sampling it is Informed RRT*: once solved, it samples only where a cheaper path
//   could pass.
// Any of them may be followed by shortcut smoothing (ShortcutSmoother.h).
//
// Exact junctions. Start-tree edges start at their parent's pose with the parent's arrival
// wheel speeds, and a node's pose is the exact end of its edge. Edges into nodes that other
// edges already leave (rewired RRT* nodes, goal-tree nodes, connections to goal-tree nodes) are
// steered in kExact mode and end exactly at the node, at rest; the edges leaving such nodes are
// steered from rest, and where the wheel speeds would jump at a junction the robot stands still
// for one period (PathSegment.h). Only the last edge, into a goal root, ends within the goal
// tolerance. A candidate solution (tree edges plus the new connection) is joined first and
// validated as a whole, so the trajectory returned is exactly the one checked; RRT* validates
// its best plan as a whole once more at the end, and smoothing its result.

#include <cstdint>
#include <string>
#include <vector>

#include "parksim/core/Pose2.h"
#include "parksim/core/RobotDef.h"
#include "parksim/core/Scenario.h"
#include "parksim/core/Trajectory.h"
#include "parksim/planner/MotionValidator.h"
#include "parksim/planner/PathCost.h"
#include "parksim/planner/SteeringFunction.h"

namespace parksim {

/// The planner list: every planner `plan`, `run` and `bench` accept (the tree planner's
/// variants and Hybrid A*, HybridAStar.h).
enum class PlannerKind { kRrt, kRrtGoalConnect, kRrtStar, kRrtConnect, kHybridAStar };

const char* toString(PlannerKind kind);
/// Every planner kind, in a fixed order (for benchmarks and help texts).
std::vector<PlannerKind> allPlannerKinds();
/// Parses "rrt", "rrt-goal-connect", "rrt-star", "rrt-connect" or "hybrid-a-star"; throws
/// Error otherwise.
PlannerKind plannerKindFromString(const std::string& name);

struct PlannerDef {
  PlannerKind kind = PlannerKind::kRrtGoalConnect;
  std::uint64_t seed = 1;         ///< seeds the planner's own RNG (std::mt19937_64)
  int max_iterations = 2000;      ///< iteration budget (the study's max_step)
  double goal_bias = 0.05;        ///< probability of sampling a goal pose instead of a random one
  double connect_radius_m = 0.1;  ///< kRrt: SE(2) distance to the goal that triggers a to-goal try
  /// Length that turns heading into distance in the SE(2) metric, m: poses are embedded as
  /// (x, y, l cos theta, l sin theta). 0 selects the footprint radius, so a heading change moves
  /// the metric by the chord the farthest footprint corner travels.
  double heading_length_m = 0.0;
  /// Wall-time budget, s; 0 = none. For benchmarks only: results then depend on machine load,
  /// so tests and reproducible runs use max_iterations alone.
  double max_time_s = 0.0;
  bool record_tree = true;  ///< keep every tree edge in the result (for figures)

  /// Path cost = length + reverse_penalty * length driven backwards + cusp_penalty_m * cusps.
  /// RRT* minimises it, smoothing accepts only shortcuts that lower it; every plan reports it.
  double reverse_penalty = 1.0;  ///< extra cost per metre driven in reverse, m per m
  double cusp_penalty_m = 0.1;   ///< cost of one change of driving direction, m

  /// kRrtStar and the goal tree of kRrtConnect: a new node lies at most this far (SE(2) metric)
  /// from the tree node nearest to its sample, m.
  double extend_distance_m = 0.15;
  /// kRrtStar: number of nearest neighbours considered as parents and for rewiring; 0 selects
  /// k = ceil(e (1 + 1/3) ln n), the usual k-nearest RRT* rule for a 3-dimensional space.
  int rewire_neighbours = 0;
  /// kRrtStar: when > 0, use every node within this SE(2) distance instead of k-nearest, m.
  double rewire_radius_m = 0.0;
  /// kRrtStar, once solved: sample only positions whose straight-line distance from the start
  /// plus to the goal is below the best cost (Informed RRT*'s ellipse; no path through the
  /// others can be cheaper, since the cost is at least the length).
  bool informed_sampling = true;

  /// Shortcut smoothing after the planner (study 3(c)(3)); uses the planner's RNG, so it is
  /// seeded by `seed` too.
  bool smooth = false;
  int smoothing_attempts = 100;  ///< random shortcuts tried
};

enum class PlanStatus {
  kSolved,
  kIterationLimit,  ///< no valid trajectory to the goal within max_iterations
  kTimeLimit,       ///< no valid trajectory to the goal within max_time_s
  kInvalidStart,    ///< the start footprint collides
  kInvalidGoal,     ///< the goal footprint collides (in every accepted heading)
};

const char* toString(PlanStatus status);

/// Wall time spent in each phase of the search (the study's 3(b) cost breakdown), s. The phases
/// do not overlap; total_s also holds bookkeeping outside them.
struct PhaseTimes {
  double sampling_s = 0.0;
  double nearest_s = 0.0;     ///< nearest-neighbour and neighbourhood queries
  double steering_s = 0.0;    ///< steering tree extensions
  double collision_s = 0.0;   ///< validating tree extensions (and new nodes' poses)
  double goal_check_s = 0.0;  ///< steering and validating to-goal trajectories to the goal roots
  double rewiring_s = 0.0;    ///< kRrtStar: choosing parents and rewiring (steering + validation)
  double connection_s = 0.0;  ///< kRrtConnect: steering and validating tree-to-tree connections
  double smoothing_s = 0.0;   ///< shortcut smoothing
  double heuristic_s = 0.0;   ///< hybrid A*: building the obstacle heuristic's grid
  double timing_s = 0.0;      ///< re-timing the plan and its duration bound (planScenario)
  double total_s = 0.0;
};

/// One point of the solution cost history.
struct CostSample {
  double time_s = 0.0;  ///< wall time since the search started, s
  int iteration = 0;    ///< iterations completed when the solution was found
  double cost = 0.0;    ///< cost of the best solution from then on, m
};

struct PlanStats {
  int iterations = 0;
  int tree_size = 0;                  ///< start-tree nodes, including the start
  int goal_tree_size = 0;             ///< goal-tree nodes, including its roots
  int goal_attempts = 0;              ///< to-goal trajectories tried
  int connection_attempts = 0;        ///< kRrtConnect: tree-to-tree connections tried
  int rewires = 0;                    ///< kRrtStar: nodes given a cheaper parent
  int smoothing_shortcuts = 0;        ///< shortcuts smoothing kept
  long collision_queries = 0;         ///< footprint queries
  double first_solution_s = -1.0;     ///< wall time to the first solution, s; -1 if none
  int first_solution_iteration = -1;  ///< iterations completed at the first solution; -1 if none
  PhaseTimes times;
};

struct PlanResult {
  PlanStatus status = PlanStatus::kIterationLimit;
  std::string message;                 ///< one line: why it failed, or a summary when solved
  Trajectory trajectory;               ///< start to goal, exactly as validated; empty unless solved
  std::vector<Pose2> waypoints;        ///< poses where the solution's edges join, start first
  std::vector<Trajectory> tree_edges;  ///< the trees' edges at the end, if recorded
  /// Cost of `trajectory` (PlannerDef's weights), m; 0 unless solved.
  double cost = 0.0;
  /// Set by planScenario: no timing of the trajectory's geometry within the timing limits is
  /// faster than this (durationLowerBound in TimeOptimalTiming.h), s; 0 unless solved.
  double duration_lower_bound_s = 0.0;
  /// Every improvement of the best solution, in order; costs never increase and the last equals
  /// `cost`. Non-optimising planners record their one solution (and smoothing's result).
  std::vector<CostSample> cost_history;
  PlanStats stats;

  bool solved() const { return status == PlanStatus::kSolved; }
};

class TreePlanner {
 public:
  TreePlanner(const RobotDef& robot, const LotBounds& lot, const SteeringFunction& steering,
              const MotionValidator& validator, const PlannerDef& def);

  PlanResult solve(const Pose2& start, const GoalRegion& goal) const;

 private:
  RobotDef robot_;
  LotBounds lot_;
  const SteeringFunction& steering_;
  const MotionValidator& validator_;
  PlannerDef def_;
};

}  // namespace parksim
