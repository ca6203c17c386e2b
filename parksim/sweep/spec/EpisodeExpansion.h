#pragma once
// A spec's episodes: every combination of its axes, each checked as a request, in the
// canonical order (ascending episode id), which does not depend on how the spec orders its
// lists.

#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "parksim/scenario/world/World.h"
#include "parksim/sweep/spec/EpisodeParams.h"
#include "parksim/sweep/spec/SweepSpec.h"
#include "parksim/usercode/ComponentCheck.h"
#include "parksim/usercode/Components.h"

namespace parksim {

/// A world file of the sweep, read once and shared by its episodes: the world it reads as, and
/// its parsed text, to which an episode's set: values are applied as `--set` applies them.
struct SweepWorldFile {
  SweepWorldFile(std::string path, std::string text);
  std::string path;  ///< as opened
  WorldFile file;
  World world;  ///< file.read()
  /// Held while `file` is read or copied: workers read it side by side.
  mutable std::mutex mutex;
};
using SweepWorld = std::shared_ptr<const SweepWorldFile>;

/// Reads the spec's worlds (world_paths order). Throws Error naming the world file, or the
/// spec's `worlds:` line when two files name their scenario alike (ids use the name).
std::vector<SweepWorld> loadSweepWorlds(const SweepSpec& spec);

/// The planners and controllers a sweep's axes may name: parksim's own, the spec's `plugins:`
/// (loaded in order) and `extra`'s (a front-end's own, e.g. Python objects; added after them).
/// Throws Error naming the spec's line when a plugin cannot be loaded.
std::shared_ptr<const Components> loadSweepComponents(const SweepSpec& spec,
                                                      const Components* extra = nullptr);

/// One episode to run: its parameters, its id and the world it runs in.
struct SweepEpisode {
  EpisodeParams params;
  std::string id;  ///< episodeId(params)
  SweepWorld world;
  /// Where its planner and controller are found (loadSweepComponents).
  std::shared_ptr<const Components> components;
  /// The spec's tolerance overrides (points into the spec passed to expandEpisodes).
  const ToleranceOverrides* tolerance = {};
};

/// Every combination, sorted by id. `worlds` must be loadSweepWorlds(spec); the spec must
/// outlive the result. Throws Error (prefixed with the spec's file, and its line where one
/// entry is to blame) when a planner or controller is unknown or refuses its parameters, a
/// combination is not a valid request, or two combinations share an id. Each distinct planner
/// and controller with parameters is made once to check them, a plugin's in a watched process
/// with `check`'s limits (ComponentCheck.h), forked from the calling thread.
std::vector<SweepEpisode> expandEpisodes(
    const SweepSpec& spec, const std::vector<SweepWorld>& worlds,
    const std::shared_ptr<const Components>& components = builtInComponents(),
    const ComponentCheckDef& check = {});

}  // namespace parksim
