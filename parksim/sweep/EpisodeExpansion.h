#pragma once
// A spec's episodes: every combination of its axes, each checked as a request, in the
// canonical order (ascending episode id), which does not depend on how the spec orders its
// lists.

#include <memory>
#include <vector>

#include "parksim/scenario/World.h"
#include "parksim/sweep/EpisodeParams.h"
#include "parksim/sweep/SweepSpec.h"

namespace parksim {

/// A world of the sweep, loaded once and shared by its episodes.
using SweepWorld = std::shared_ptr<const World>;

/// Reads the spec's worlds (world_paths order). Throws Error naming the world file, or the
/// spec's `worlds:` line when two files name their scenario alike (ids use the name).
std::vector<SweepWorld> loadSweepWorlds(const SweepSpec& spec);

/// One episode to run: its parameters, its id and the world it runs in.
struct SweepEpisode {
  EpisodeParams params;
  std::string id;  ///< episodeId(params)
  SweepWorld world;
  /// The spec's tolerance overrides (points into the spec passed to expandEpisodes).
  const ToleranceOverrides* tolerance = {};
};

/// Every combination, sorted by id. `worlds` must be loadSweepWorlds(spec); the spec must
/// outlive the result. Throws Error (prefixed with the spec's file) when a combination is not a
/// valid request or two combinations share an id.
std::vector<SweepEpisode> expandEpisodes(const SweepSpec& spec,
                                         const std::vector<SweepWorld>& worlds);

}  // namespace parksim
