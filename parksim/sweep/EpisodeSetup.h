#pragma once
// The one place where a sweep episode's parameters become an episode request for the pipeline
// (pipeline/EpisodeRequest.h). A new axis of the sweep spec is wired here and nowhere else;
// what the parameters leave alone keeps the library's defaults, as on the command line.

#include <memory>
#include <string>
#include <vector>

#include "parksim/pipeline/EpisodeRequest.h"
#include "parksim/scenario/World.h"
#include "parksim/sweep/EpisodeParams.h"

namespace parksim {

/// Values the timing axis accepts: every timing. (The realism axis accepts realismChoices(),
/// realism/RealismDef.h.)
std::vector<std::string> supportedTimings();

/// The request for `params` in `world`, with the spec's tolerance overrides. The world is
/// shared unless an offset moves the start or the goal (then it is a copy with them moved).
/// Throws Error when a value is unknown or an offset puts the start or the goal where the world
/// reader would not accept it (outside the lot, too close to an obstacle).
EpisodeRequest episodeRequest(const EpisodeParams& params,
                              const std::shared_ptr<const World>& world,
                              const ToleranceOverrides& tolerance);

/// The other way: the parameters a request states (a `parksim run`'s, for its records), with
/// the world's scenario name and file. Offsets are zero (a run moves the start or goal in its
/// world, not by an offset).
EpisodeParams episodeParamsOf(const EpisodeRequest& request);

}  // namespace parksim
