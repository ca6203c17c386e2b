// The plugin's one entry point: its name, its version, and what it registers.

#include "ExamplePlugins.h"

namespace {

void registerComponents(parksim::PluginRegistrar& r) {
  r.addPlanner(example::gridPlanner());
  r.addController(example::purePursuit());
}

}  // namespace

PARKSIM_PLUGIN("parksim-examples", "1.0.0", registerComponents)
