#include "parksim/usercode/Components.h"

#include "parksim/usercode/CommandController.h"
#include "parksim/usercode/CommandLine.h"
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

std::string plannerOrigin(const Components& components, const PlannerInfo& info,
                          const ParamMap& params) {
  if (info.trusted) return {};
  for (const PluginRecord& p : components.plugins) {
    if (p.name == info.plugin) {
      return "plugin " + p.name + " " + p.version + " (" + p.path + ", FNV-1a " + p.hash + ")";
    }
  }
  if (info.own_process) {
    const auto command = params.find(kCommandParam);
    return "command `" + (command == params.end() ? std::string() : command->second) + "`";
  }
  return info.origin.empty() ? "user code " + info.name : info.origin;
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
