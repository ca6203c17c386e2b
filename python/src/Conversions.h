#pragma once
// Types shared between binding files whose Python classes convert into core types.

#include <memory>

#include <pybind11/pybind11.h>

#include "parksim/core/Scenario.h"
#include "parksim/planner/PlanScenario.h"
#include "python/src/Bindings.h"

namespace parksim::python {

/// A plan with what made it: parksim.PlanResult.
struct PlanOutcome {
  std::shared_ptr<const Scenario> scenario;
  PlanSetup setup;
  PlanResult result;
};

/// plan()'s options taken from `options` (removed from it): planner, steering, PlannerDef and
/// PlanSetup fields.
PlanSetup planSetupFrom(py::dict& options);

/// Plans with the GIL released.
PlanOutcome planWorld(const World& world, const PlanSetup& setup);

}  // namespace parksim::python
