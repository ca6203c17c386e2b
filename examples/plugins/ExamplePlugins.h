#pragma once
// The example plugin's two components, each in its own file; ExamplePlugin.cpp registers them.

#include "parksim/usercode/PluginApi.h"

namespace example {

/// `example`: A* over a grid of positions, joined by the problem's steering function.
parksim::PlannerEntry gridPlanner();
/// `pure-pursuit`: pure pursuit of a point ahead on the plan, in time.
parksim::ControllerEntry purePursuit();

}  // namespace example
