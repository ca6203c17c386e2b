#include "parksim/plugin/Components.h"

#include "parksim/command/CommandController.h"
#include "parksim/command/CommandPlanner.h"

namespace parksim {

PlannerRegistry ownPlanners() {
  PlannerRegistry r = builtInPlanners();
  r.add(commandPlannerEntry());
  return r;
}

ControllerRegistry ownControllers() {
  ControllerRegistry r = builtInControllers();
  r.add(commandControllerEntry());
  return r;
}

}  // namespace parksim
