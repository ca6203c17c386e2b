#pragma once
// The planning options every planning command takes (--planner, --planner-param,
// --planner-command, --steering, --seed, --max-iterations, --time-limit, --smooth,
// --smoothing-attempts, --timing,
// --feedback-headroom, --turning-radius). Their defaults are the library's (PlanSetup{}): the
// command line states them, it does not choose them.

#include <cstdint>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "parksim/core/model/Scenario.h"
#include "parksim/planner/base/PlanScenario.h"

namespace parksim::cli {

/// Bounds of the planning options (docs/limits.md): the tree and its edges stay in memory.
inline constexpr int kMaxPlannerIterations = 1'000'000;
inline constexpr int kMaxSmoothingAttempts = 100'000;

/// Options every planning command takes. Each starts at the library's default (PlanSetup{}), so
/// a command line that names none plans exactly as a sweep or Python does.
struct PlanCliOptions {
  std::string planner = PlanSetup{}.planner;
  /// --planner-param NAME=VALUE, repeatable: the planner's own parameters (ParamMap.h).
  std::vector<std::string> planner_params;
  /// --planner-command 'CMD ... {problem} {out}': the planner `command` with this command line
  /// as its `command` parameter (usercode/CommandPlanner.h); excludes --planner.
  std::string planner_command;
  std::string steering = toString(PlanSetup{}.steering_kind);
  std::uint64_t seed = PlanSetup{}.search.seed;
  std::string max_iterations = "auto";  ///< "auto": kAutoIterations, the lot's budget
  double time_limit_s = PlanSetup{}.search.max_time_s;
  bool smooth = PlanSetup{}.search.smooth;
  int smoothing_attempts = PlanSetup{}.search.smoothing_attempts;
  std::string timing = toString(PlanSetup{}.timing);
  double feedback_headroom = PlanSetup{}.feedback_headroom;
  double turning_radius_m = PlanSetup{}.reeds_shepp.turning_radius_m;

  /// Registers the options on `sub`; --planner's help lists `planners` (the built-in ones and
  /// those of the plugins loaded when the help is shown).
  void addTo(CLI::App& sub, const PlannerRegistry& planners = builtInPlanners());
  /// The planning setup these options select (automatic choices left to resolvedPlanSetup).
  /// Throws Error on bad values.
  PlanSetup toSetup() const;
};

/// "auto" -> kAutoIterations; otherwise an integer in [1, kMaxPlannerIterations]. Throws Error
/// naming `option` on anything else.
int parseIterationBudget(const std::string& text, const std::string& option = "--max-iterations");

}  // namespace parksim::cli
