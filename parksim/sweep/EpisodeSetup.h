#pragma once
// The one place where an episode's parameters become the inputs of planning and simulation.
// A new axis of the sweep spec (a realism preset's noise, a timing option) is wired here and
// nowhere else.

#include <string>
#include <vector>

#include "parksim/core/Scenario.h"
#include "parksim/planner/PlanScenario.h"
#include "parksim/sim/ExecutionDef.h"
#include "parksim/sweep/EpisodeParams.h"

namespace parksim {

struct EpisodeSetup {
  Scenario scenario;  ///< the world with the episode's start and goal offsets applied
  PlanSetup plan;
  ExecutionDef execution;
};

/// Values each axis accepts in this build (the spec reader checks against these).
/// Issue 8 adds realism presets beyond "ideal" (and with them noise seeds other than 0);
/// issue 9 adds timings beyond "study".
const std::vector<std::string>& supportedRealismPresets();
const std::vector<std::string>& supportedTimings();

/// `world` with `params` applied. Throws Error when a value is unknown or an offset moves the
/// start or the goal outside the lot bounds.
EpisodeSetup setupEpisode(const EpisodeParams& params, const Scenario& world);

}  // namespace parksim
