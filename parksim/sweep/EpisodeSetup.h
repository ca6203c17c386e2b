#pragma once
// The one place where an episode's parameters become the inputs of planning and simulation.
// A new axis of the sweep spec (a realism preset's noise, a timing option) is wired here and
// nowhere else.

#include <string>
#include <vector>

#include "parksim/core/Scenario.h"
#include "parksim/planner/PlanScenario.h"
#include "parksim/sim/ExecutionDef.h"
#include "parksim/sim/TrackingTolerance.h"
#include "parksim/sweep/EpisodeExpansion.h"
#include "parksim/sweep/EpisodeParams.h"
#include "parksim/sweep/SweepSpec.h"

namespace parksim {

struct EpisodeSetup {
  Scenario scenario;  ///< the world with the episode's start and goal offsets applied
  PlanSetup plan;
  ExecutionDef execution;
  TrackingTolerance tolerance;  ///< the world's (or parksim's default) with the spec's overrides
};

/// Values the realism and timing axes accept: "world" and every realism preset; every timing.
std::vector<std::string> supportedRealismPresets();
std::vector<std::string> supportedTimings();

/// `world` with `params` applied. Throws Error when a value is unknown or an offset puts the
/// start or the goal where the world reader would not accept it (outside the lot, too close to
/// an obstacle).
EpisodeSetup setupEpisode(const EpisodeParams& params, const SweepWorld& world,
                          const ToleranceOverrides& tolerance);

}  // namespace parksim
