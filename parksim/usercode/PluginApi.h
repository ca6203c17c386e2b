#pragma once
// The one header a plugin includes: planners (planner/base/Planner.h) and controllers
// (sim/control/Controller.h) a shared library adds to parksim, registered through one exported
// entry point that carries the plugin API version it was built against (nav2 and MoveIt load
// planners and controllers the same way; docs/your-code.md).
//
//   #include "parksim/usercode/PluginApi.h"
//
//   void registerMine(parksim::PluginRegistrar& r) {
//     r.addPlanner(parksim::plannerEntry<MyPlanner>({.name = "mine", .description = "..."},
//                                                    MyPlannerDef{}, &bindMine));
//     r.addController(...);
//   }
//   PARKSIM_PLUGIN("my-plugin", "1.2.0", registerMine)
//
// Build it with the installed package's helper: find_package(parksim) then
// parksim_add_plugin(my_plugin SOURCES mine.cpp); load it with `--plugin PATH` (plan, run,
// render, sweep, list, parksim-bench) or `plugins:` in a sweep spec. A plugin built against
// another API version, or against headers whose types differ in layout, is refused in one line.

#include <cstdint>
#include <string>

#include "parksim/planner/base/Planner.h"
#include "parksim/sim/control/Controller.h"

/// Bumped whenever a type a plugin sees changes meaning; a plugin must match it exactly.
/// 2: Controller::carCommand and ControllerInput's car fields (issue 38).
#define PARKSIM_PLUGIN_API_VERSION 2

namespace parksim {

/// What a plugin's registration function adds components through.
class PluginRegistrar {
 public:
  virtual ~PluginRegistrar() = default;
  virtual void addPlanner(PlannerEntry entry) = 0;
  virtual void addController(ControllerEntry entry) = 0;
};

/// Layout of the types that cross between parksim and a plugin, as the compiler that builds
/// either saw them: two builds agree only when every size agrees (a plugin built against
/// headers of another parksim build refuses to load even when the API version matches).
constexpr std::uint64_t pluginAbiFingerprint() {
  std::uint64_t h = 1469598103934665603ULL;
  for (std::uint64_t size :
       {sizeof(PlanningProblem), sizeof(PlanResult), sizeof(PlannerEntry), sizeof(SearchDef),
        sizeof(Scenario), sizeof(Trajectory), sizeof(ControllerSetup), sizeof(ControllerInput),
        sizeof(ControllerEntry), sizeof(std::string), sizeof(ParamInfo)}) {
    h = (h ^ size) * 1099511628211ULL;
  }
  return h;
}

/// What the exported entry point returns.
struct PluginDescriptor {
  int api_version;                ///< PARKSIM_PLUGIN_API_VERSION when the plugin was built
  std::uint64_t abi_fingerprint;  ///< pluginAbiFingerprint() when the plugin was built
  const char* name;               ///< the plugin's name, e.g. "my-plugin"
  const char* version;            ///< its own version, recorded with every result
  void (*register_components)(PluginRegistrar&);
};

/// The exported entry point's symbol.
inline constexpr const char* kPluginEntryPoint = "parksim_plugin";

}  // namespace parksim

/// Defines the plugin's one exported entry point.
#define PARKSIM_PLUGIN(NAME, VERSION, REGISTER_FUNCTION)                                     \
  extern "C" __attribute__((visibility("default"))) const parksim::PluginDescriptor*         \
  parksim_plugin() {                                                                         \
    static const parksim::PluginDescriptor descriptor{PARKSIM_PLUGIN_API_VERSION,            \
                                                      parksim::pluginAbiFingerprint(), NAME, \
                                                      VERSION, REGISTER_FUNCTION};           \
    return &descriptor;                                                                      \
  }
