#pragma once
// One benchmark run as a row of bench.csv: which library and planner, on which scenario and seed,
// under which budget, and what came out. parksim and OMPL runs share the row so that one table
// and one CSV compare them; fields a library does not report stay empty (NaN or -1).

#include <cstdint>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace parksim::bench {

inline constexpr double kNotMeasured = std::numeric_limits<double>::quiet_NaN();

struct BenchRecord {
  std::string library;   ///< "parksim" or "ompl"
  std::string planner;   ///< parksim: planner kind ("rrt", ...); OMPL: "RRT", "RRTConnect", ...
  std::string space;     ///< parksim: steering function; OMPL: state space ("reeds-shepp", "se2")
  std::string scenario;  ///< Scenario::name
  std::uint64_t seed = 0;
  std::string budget;  ///< what ends the run, e.g. "iterations=2000" or "time=1s"

  bool solved = false;
  std::string status;  ///< the library's own status name ("solved", "Exact solution", ...)
  /// Verdict of parksim's exact path check (bench/planning/PathCheck.h); false when unsolved.
  bool valid = false;

  double time_first_s = kNotMeasured;  ///< wall time to the first solution, s
  double time_total_s = kNotMeasured;  ///< wall time of the whole run, s
  /// CPU time of the whole run, s: unlike wall time, barely affected by other processes
  /// competing for the cores, so it cross-checks wall-time ratios on a shared machine.
  double cpu_total_s = kNotMeasured;
  double length_m = kNotMeasured;  ///< length travelled by the reference point, m
  int cusps = -1;                  ///< direction reversals along the path
  /// parksim: duration of the planned trajectory, s (as timed: time-optimal by default).
  double duration_s = kNotMeasured;
  /// parksim: lower bound on any timing of the path's geometry (TimeOptimalTiming.h), s.
  double duration_lower_bound_s = kNotMeasured;
  /// parksim: lower bound on any plan from the start to the goal at the same limits, around any
  /// obstacles (FreeSpaceBound.h), s.
  double free_space_bound_s = kNotMeasured;
  /// parksim: the planner's cost: path cost (length + reverse and cusp penalties, PathCost.h), m,
  /// or the plan's duration, s, for planners that minimise it (time-a-star).
  double cost = kNotMeasured;
  double min_clearance_m = kNotMeasured;  ///< smallest footprint-obstacle distance along the path
  /// parksim: changes of turning direction per metre of path (PlanShape.h), 1/m.
  double steering_reversals_per_m = kNotMeasured;

  long iterations = -1;         ///< parksim: iterations of the tree loop
  long iterations_first = -1;   ///< parksim: iterations completed at the first solution
  long tree_size = -1;          ///< parksim: nodes of all trees; OMPL: planner graph vertices
  long collision_queries = -1;  ///< parksim: footprint queries of the planner itself
  /// parksim: wall time per phase of the search, s, as (name, seconds), in the planner's order.
  std::vector<std::pair<std::string, double>> phases_s;
  /// The best solution cost over the run as (wall time s, cost m) pairs, in time order; empty
  /// when not recorded. Written to OMPL logs as progress properties (Planner Arena plots them).
  std::vector<std::pair<double, double>> progress;
};

}  // namespace parksim::bench
