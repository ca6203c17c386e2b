#pragma once
// The one place where a sweep episode's parameters become an episode request for the pipeline
// (pipeline/EpisodeRequest.h). A new axis of the sweep spec is wired here and nowhere else;
// what the parameters leave alone keeps the library's defaults, as on the command line.

#include <memory>
#include <string>
#include <vector>

#include "parksim/pipeline/EpisodeRequest.h"
#include "parksim/scenario/world/World.h"
#include "parksim/sweep/spec/EpisodeExpansion.h"
#include "parksim/sweep/spec/EpisodeParams.h"

namespace parksim {

/// Values the timing axis accepts: every timing. (The realism axis accepts realismChoices(),
/// realism/RealismDef.h.)
std::vector<std::string> supportedTimings();

/// The world of `params` in `file`: the file's own (shared) without set: world values, else
/// the file's text read again with them applied, each as `--set PATH=VALUE` applies it (its
/// messages start "set: PATH=VALUE: "). World values change the world, not its name. Throws
/// Error as the world reader does.
std::shared_ptr<const World> episodeWorld(const EpisodeParams& params, const SweepWorld& file);

/// The same read from `own`, a copy of file->file that this thread alone uses (no lock).
std::shared_ptr<const World> episodeWorld(const EpisodeParams& params, const SweepWorld& file,
                                          const WorldFile& own);

/// The request for `params` in `world` (episodeWorld), with the spec's tolerance overrides. The
/// world is shared unless an offset moves the start or the goal (then it is a copy with them
/// moved). Throws Error when a value is unknown or an offset puts the start or the goal where the
/// world reader would not accept it (outside the lot, too close to an obstacle).
EpisodeRequest episodeRequest(const EpisodeParams& params,
                              const std::shared_ptr<const World>& world,
                              const ToleranceOverrides& tolerance,
                              const std::shared_ptr<const Components>& components = nullptr);

/// The other way: the parameters a request states (a `parksim run`'s, for its records), with
/// the world's scenario name and file. Offsets are zero (a run moves the start or goal in its
/// world, not by an offset).
EpisodeParams episodeParamsOf(const EpisodeRequest& request);

}  // namespace parksim
