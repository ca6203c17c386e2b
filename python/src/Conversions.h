#pragma once
// Types shared between binding files whose Python classes convert into core types.

#include <memory>
#include <optional>

#include <pybind11/pybind11.h>

#include "parksim/core/model/Scenario.h"
#include "parksim/core/params/ParamMap.h"
#include "parksim/pipeline/EpisodeOutcome.h"
#include "parksim/pipeline/EpisodeRequest.h"
#include "parksim/pipeline/Verdict.h"
#include "parksim/planner/base/PlanScenario.h"
#include "python/src/Bindings.h"

namespace parksim::python {

/// A plan with what made it: parksim.PlanResult.
struct PlanOutcome {
  std::shared_ptr<const Scenario> scenario;
  PlanSetup setup;  ///< as used (automatic choices made)
  /// The planner's result; none when the planner failed (the verdict is planner_error).
  std::optional<PlanResult> result;
  nlohmann::json summary;  ///< plan.json's content
  /// The pipeline's verdict on the plan: met when it may be driven, else plan_failed,
  /// plan_invalid or planner_error with the reason (pipeline/Verdict.h).
  Verdict verdict;

  /// The planner's status ("solved", "iteration_limit", ..., "plan_invalid"), or the verdict's
  /// when there is no result ("planner_error").
  std::string status() const;
  /// The planner's message, or the verdict's reason when there is no result.
  std::string message() const;
};

/// The plan part of a pipeline outcome that planned (outcome.plan_setup, plan, plan_summary,
/// and the verdict on the plan: met when solved, else the outcome's).
PlanOutcome planOutcomeOf(const std::shared_ptr<const Scenario>& scenario,
                          const EpisodeOutcome& outcome);

/// plan()'s options taken from `options` (removed from it): planner, planner_params, steering,
/// SearchDef and PlanSetup fields, over the library's defaults.
PlanSetup planSetupFrom(py::dict& options);

/// plan()'s and run()'s isolate, planner_timeout and controller_timeout (s) (RunRequest.cpp).
struct IsolationOptions {
  bool isolate = false;
  std::optional<double> planner_s;
  std::optional<double> controller_tick_s;

  /// Sets request.limits and says whether to run in a worker. A time limit given for code that
  /// would run in this process (no isolate) is a TypeError: it could not hold; a limit out of
  /// range an Error. Call it once the request's components and plan are known.
  bool applyTo(EpisodeRequest& request) const;
};

/// The options above, taken from `options` (removed from it).
IsolationOptions takeIsolation(py::dict& options);

/// The pipeline's outcome of `request`: in this process with the GIL released, or with
/// `isolate` in a watched worker forked from the calling thread (pipeline/IsolatedEpisode.h),
/// the interpreter's fork handling around the fork.
EpisodeOutcome runRequest(const EpisodeRequest& request, bool isolate);

/// Plans through the episode pipeline (a request that does not drive), as runRequest runs it.
PlanOutcome planWorld(const WorldHandle& world, const EpisodeRequest& request,
                      bool isolate = false);

/// A dict of planner or controller parameters ({"goal_bias": 0.1}) as a ParamMap: bools as
/// true/false, numbers in their shortest round-trip form, strings as they are; anything else is
/// a TypeError naming `what`.
ParamMap paramsFrom(const py::handle& dict, const char* what);

}  // namespace parksim::python
