#pragma once
// Shared by `parksim plan` and `parksim run`: planner options on the command line, and the
// plan's files (trajectory.csv, plan.json).

#include <string>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "parksim/core/Scenario.h"
#include "parksim/planner/PlanScenario.h"

namespace parksim::app {

/// Bounds of the planning options (docs/limits.md): the tree and its edges stay in memory.
inline constexpr int kMaxPlannerIterations = 1'000'000;
inline constexpr int kMaxSmoothingAttempts = 100'000;

/// Options every planning command takes: --planner, --steering, --seed, --max-iterations,
/// --time-limit, --smooth, --smoothing-attempts, --timing, --feedback-headroom,
/// --turning-radius.
struct PlanCliOptions {
  std::string planner = "hybrid-a-star";
  std::string steering = "reeds-shepp";
  std::uint64_t seed = 1;
  std::string max_iterations = "auto";
  double time_limit_s = 0.0;
  bool smooth = false;
  int smoothing_attempts = 100;
  std::string timing = "time-optimal";
  double feedback_headroom = 0.2;
  double turning_radius_m = 0.05;

  /// Registers the options on `sub`.
  void addTo(CLI::App& sub);
  /// The planning setup these options select for `scenario`. Throws Error on bad values.
  PlanSetup toSetup(const Scenario& scenario) const;
};

/// "auto" -> defaultIterationBudget(kind, lot); otherwise a non-negative integer. Throws Error
/// naming `option` on anything else.
int parseIterationBudget(const std::string& text, PlannerKind kind, const LotBounds& lot,
                         const std::string& option = "--max-iterations");

/// plan.json's content: status, planner, steering, seed, iterations, tree sizes, per-phase
/// times, planning_time_s, first solution, cost and its history, path_length_m, cusps, final
/// pose error.
nlohmann::json planSummary(const Scenario& scenario, const PlanSetup& setup,
                           const PlanResult& result);

/// The statistics a trajectory carries by itself, for a plan the planner did not make (a plan
/// file, a Python array): path_length_m, duration_s, cusps, final pose error.
nlohmann::json trajectorySummary(const Scenario& scenario, const Trajectory& plan);

/// `j` as indented text with a final newline. Strings that are not UTF-8 (names and paths
/// from input files) are written with U+FFFD in place of their bad bytes instead of failing.
std::string jsonText(const nlohmann::json& j);

/// Adds planSummary's keys to a flat metrics.json with a plan_ prefix: nested objects flattened
/// as plan_<key>.<sub>; arrays (the RRT* cost history) and provenance stay in plan.json.
/// Shared by `parksim run` and the Python module, whose metrics must match key for key.
void addPlanKeys(nlohmann::json& metrics, const nlohmann::json& summary);

/// Writes DIR/trajectory.csv (only if solved) and DIR/plan.json, creating DIR.
void writePlanFiles(const std::string& dir, const Scenario& scenario, const PlanSetup& setup,
                    const PlanResult& result);

}  // namespace parksim::app
