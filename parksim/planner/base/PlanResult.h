#pragma once
// What every planner returns (TreePlanner, HybridAStar): a status, the trajectory exactly as it
// was validated, and the statistics of the search.

#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "parksim/core/geometry/Pose2.h"
#include "parksim/core/model/Trajectory.h"

namespace parksim {

enum class PlanStatus {
  kSolved,
  kIterationLimit,  ///< no valid trajectory to the goal within max_iterations
  kTimeLimit,       ///< no valid trajectory to the goal within max_time_s
  kInvalidStart,    ///< the start footprint collides
  kInvalidGoal,     ///< the goal footprint collides (in every accepted heading)
  kCancelled,       ///< SearchDef::cancel was set before a trajectory to the goal was found
  /// Set by parksim alone (planScenario), never by a planner: the solved plan of a planner that
  /// is not parksim's own failed the check before driving (PlanCheck.h); the message says where.
  kPlanInvalid,
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

/// Every phase (not total_s) by name with its time, s, in one order: the one list that
/// plan.json's phase_times_s, a result row's plan_phase_times_s and the benchmark's
/// phase_<name>_s columns are made from.
std::vector<std::pair<const char*, double>> phaseTimeList(const PhaseTimes& times);

/// What a plan's cost measures.
enum class PlanObjective {
  kPathCost,  ///< length plus reverse and cusp penalties (PathCost.h), m: "path_cost"
  kDuration,  ///< the plan's duration as timed, s: "duration"
};

const char* toString(PlanObjective objective);

/// One point of the solution cost history.
struct CostSample {
  double time_s = 0.0;  ///< wall time since the search started, s
  int iteration = 0;    ///< iterations completed when the solution was found
  double cost = 0.0;    ///< cost of the best solution from then on (m or s: PlanResult::objective)
};

struct PlanStats {
  int iterations = 0;
  int tree_size = 0;                  ///< start-tree nodes, including the start
  int goal_tree_size = 0;             ///< goal-tree nodes, including its roots
  int goal_attempts = 0;              ///< to-goal trajectories tried
  int connection_attempts = 0;        ///< kRrtConnect: tree-to-tree connections tried
  int rewires = 0;                    ///< kRrtStar: nodes given a cheaper parent
  int smoothing_shortcuts = 0;        ///< shortcuts smoothing kept
  int smoothing_fillets = 0;          ///< corners smoothing turned into arcs (PathSmoother.h)
  long collision_queries = 0;         ///< footprint queries
  double first_solution_s = -1.0;     ///< wall time to the first solution, s; -1 if none
  int first_solution_iteration = -1;  ///< iterations completed at the first solution; -1 if none
  PhaseTimes times;
};

struct PlanResult {
  PlanStatus status = PlanStatus::kIterationLimit;
  std::string message;  ///< one line: why it failed, or a summary when solved
  /// Start to goal, exactly as validated; empty unless solved, or kPlanInvalid (then the plan
  /// that failed its check, kept to be looked at, never driven).
  Trajectory trajectory;
  std::vector<Pose2> waypoints;        ///< poses where the solution's edges join, start first
  std::vector<Trajectory> tree_edges;  ///< the trees' edges at the end, if recorded
  /// Cost of `trajectory`, 0 unless solved: its path cost with PlannerDef's weights (m), or its
  /// duration (s) for planners that minimise duration (`objective`).
  double cost = 0.0;
  PlanObjective objective = PlanObjective::kPathCost;
  /// Set by planScenario: no timing of the trajectory's geometry within the timing limits is
  /// faster than this (durationLowerBound in TimeOptimalTiming.h), s; 0 unless solved.
  double duration_lower_bound_s = 0.0;
  /// Set by planScenario: no plan from the start to the goal within the timing limits, around
  /// any obstacles, is faster than this (freeSpaceDurationBound in FreeSpaceBound.h: the
  /// Balkcom-Mason optimum with the acceleration ramps from and to rest), s; 0 unless solved.
  double free_space_bound_s = 0.0;
  /// Every improvement of the best solution, in order; the last equals `cost`. Costs never
  /// increase, except that smoothing, which makes a plan faster, may lengthen a path cost (m):
  /// its result is recorded as it is. Non-optimising planners record their one solution (and
  /// smoothing's result).
  std::vector<CostSample> cost_history;
  PlanStats stats;

  bool solved() const { return status == PlanStatus::kSolved; }
};

/// Called by a planner as its search advances: `done` of at most `budget` iterations (tree
/// planners) or node expansions (Hybrid A*). A search that succeeds stops before its budget.
/// For progress displays: it must be cheap and must not throw.
using PlanProgress = std::function<void(long done, long budget)>;

}  // namespace parksim
