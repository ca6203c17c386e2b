#pragma once
// A spec's episodes: every combination of its axes, each checked by setupEpisode, in the
// canonical order (ascending episode id), which does not depend on how the spec orders its
// lists.

#include <vector>

#include "parksim/core/Scenario.h"
#include "parksim/scenario/RealismReader.h"
#include "parksim/sweep/EpisodeParams.h"
#include "parksim/sweep/SweepSpec.h"

namespace parksim {

/// A world of the sweep: its scenario and its realism: and tolerance: sections.
struct SweepWorld {
  Scenario scenario;
  WorldRealism realism;
};

/// Reads the spec's worlds (world_paths order). Throws Error naming the world file, or the
/// spec's `worlds:` line when two files name their scenario alike (ids use the name).
std::vector<SweepWorld> loadSweepWorlds(const SweepSpec& spec);

/// One episode to run: its parameters, its id and the world it runs in.
struct SweepEpisode {
  EpisodeParams params;
  std::string id;                ///< episodeId(params)
  const SweepWorld* world = {};  ///< points into the worlds passed to expandEpisodes
  /// The spec's tolerance overrides (points into the spec passed to expandEpisodes).
  const ToleranceOverrides* tolerance = {};
};

/// Every combination, sorted by id. `worlds` must be loadSweepWorlds(spec); both must outlive
/// the result. Throws Error (prefixed with the spec's file) when setupEpisode rejects a combination
/// or two combinations share an id.
std::vector<SweepEpisode> expandEpisodes(const SweepSpec& spec,
                                         const std::vector<SweepWorld>& worlds);

}  // namespace parksim
