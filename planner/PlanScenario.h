#pragma once
// Plans a scenario end to end: the study's controller as steering, gap-free motion validation
// against the given footprint checker, and the tree planner.

#include "core/FootprintChecker.h"
#include "core/Scenario.h"
#include "planner/MotionValidator.h"
#include "planner/MoveToPoseSteering.h"
#include "planner/TreePlanner.h"

namespace parksim {

struct PlanSetup {
  PlannerDef planner;
  /// The to-goal tolerance is taken from the scenario's goal region.
  MoveToPoseDef steering;
  MotionValidatorDef validation;
};

PlanResult planScenario(const Scenario& scenario, const FootprintChecker& checker,
                        const PlanSetup& setup);

}  // namespace parksim
