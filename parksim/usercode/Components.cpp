#include "parksim/usercode/Components.h"

#include "parksim/usercode/CommandController.h"
#include "parksim/usercode/CommandPlanner.h"

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

std::string pluginsProvenance(const Components& components) {
  std::string text;
  for (const PluginRecord& p : components.plugins) {
    if (!text.empty()) text += "; ";
    text += p.name + " " + p.version + " " + p.hash;
  }
  return text;
}

}  // namespace parksim
