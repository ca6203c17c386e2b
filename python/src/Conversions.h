#pragma once
// Types shared between binding files whose Python classes convert into core types.

#include <memory>

#include <pybind11/pybind11.h>

#include "parksim/core/model/Scenario.h"
#include "parksim/core/params/ParamMap.h"
#include "parksim/pipeline/EpisodeRequest.h"
#include "parksim/planner/base/PlanScenario.h"
#include "python/src/Bindings.h"

namespace parksim::python {

/// A plan with what made it: parksim.PlanResult.
struct PlanOutcome {
  std::shared_ptr<const Scenario> scenario;
  PlanSetup setup;  ///< as used (automatic choices made)
  PlanResult result;
  nlohmann::json summary;  ///< plan.json's content
};

/// plan()'s options taken from `options` (removed from it): planner, planner_params, steering,
/// SearchDef and PlanSetup fields, over the library's defaults.
PlanSetup planSetupFrom(py::dict& options);

/// Plans through the episode pipeline (a request that does not drive), the GIL released.
PlanOutcome planWorld(const WorldHandle& world, const EpisodeRequest& request);

/// A dict of planner or controller parameters ({"goal_bias": 0.1}) as a ParamMap: bools as
/// true/false, numbers in their shortest round-trip form, strings as they are; anything else is
/// a TypeError naming `what`.
ParamMap paramsFrom(const py::handle& dict, const char* what);

}  // namespace parksim::python
