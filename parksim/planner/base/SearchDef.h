#pragma once
// What every search is given besides its own parameters: the budget, the seed, what to record
// and the cost it reports. PlanSetup holds one (PlanSetup::search), and its initializers here are
// parksim's defaults, the only ones: a planner's own Def (TreePlannerDef, HybridAStarDef,
// TimeAStarDef) holds only what that planner alone reads.

#include <atomic>
#include <cstdint>

namespace parksim {

/// SearchDef::max_iterations: the planner's budget for the lot (PlannerInfo::default_budget),
/// resolved when the plan is made (resolvedPlanSetup).
inline constexpr int kAutoIterations = 0;

struct SearchDef {
  std::uint64_t seed = 1;  ///< seeds the planner's own RNG (and smoothing's, derived from it)
  /// Iterations (tree planners) or node expansions (A* planners); kAutoIterations: the
  /// planner's budget for the lot.
  int max_iterations = kAutoIterations;
  /// Wall-time budget, s; 0 = none. For benchmarks only: results then depend on machine load,
  /// so tests and reproducible runs use max_iterations alone.
  double max_time_s = 0.0;
  /// When set and true, the search stops at its next check and reports what it has (a cancel
  /// button, a sweep being stopped). Not owned.
  const std::atomic<bool>* cancel = nullptr;
  bool record_tree = true;  ///< keep every tree edge in the result (for figures)

  /// Path cost = length + reverse_penalty * length driven backwards + cusp_penalty_m * cusps.
  /// RRT* minimises it, smoothing accepts only shortcuts that lower it; every plan reports it.
  double reverse_penalty = 1.0;  ///< extra cost per metre driven in reverse, m per m
  double cusp_penalty_m = 0.1;   ///< cost of one change of driving direction, m

  /// Smooth the plan the planner found (PathSmoother.h with time-optimal timing; a tree
  /// planner's shortcut smoothing with study timing); its random shortcuts are drawn from a
  /// stream seeded by `seed`.
  bool smooth = true;
  int smoothing_attempts = 300;  ///< random shortcuts tried

  /// True once `cancel` is set.
  bool cancelled() const { return cancel != nullptr && cancel->load(std::memory_order_relaxed); }
};

}  // namespace parksim
