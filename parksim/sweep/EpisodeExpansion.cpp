#include "parksim/sweep/EpisodeExpansion.h"

#include <algorithm>

#include "parksim/core/Error.h"
#include "parksim/pipeline/EpisodeSettings.h"
#include "parksim/sweep/EpisodeSetup.h"

namespace parksim {

std::vector<SweepWorld> loadSweepWorlds(const SweepSpec& spec) {
  std::vector<SweepWorld> worlds;
  for (std::size_t i = 0; i < spec.world_paths.size(); ++i) {
    const std::vector<ScenarioOverride> none;
    const std::vector<ScenarioOverride>& set =
        i < spec.world_overrides.size() ? spec.world_overrides[i] : none;
    World world = loadWorld(spec.world_paths[i], set);
    // A variant of a world (`set:`) is named by its overrides: its episodes get ids of their own.
    if (!set.empty()) {
      std::string variant;
      for (const ScenarioOverride& o : set) {
        variant += (variant.empty() ? "" : ",") + o.path + "=" + o.value;
      }
      world.scenario.name += "{" + variant + "}";
    }
    worlds.push_back(std::make_shared<const World>(std::move(world)));
    for (std::size_t j = 0; j < i; ++j) {
      if (worlds[j]->scenario.name == worlds[i]->scenario.name) {
        throw Error(spec.source_path + ":" + std::to_string(spec.worlds_line) +
                    ": worlds: " + spec.world_files[j] + " and " + spec.world_files[i] +
                    " both name their scenario '" + worlds[i]->scenario.name +
                    "' (episode ids use the name; rename one)");
      }
    }
  }
  return worlds;
}

namespace {

// Each offset on each world, before the product: an offset that leaves the robot outside the
// lot or on an obstacle is named by its line in the spec.
void checkOffsets(const SweepSpec& spec, const std::vector<SweepWorld>& worlds) {
  const auto check = [&](const std::vector<PoseOffset>& offsets, const std::vector<int>& lines,
                         const char* key, bool start) {
    for (std::size_t i = 0; i < offsets.size(); ++i) {
      for (const SweepWorld& world : worlds) {
        EpisodeParams p;
        (start ? p.start_offset : p.goal_offset) = offsets[i];
        try {
          (void)episodeRequest(p, world, spec.tolerance);
        } catch (const Error& e) {
          const int line = i < lines.size() ? lines[i] : 0;
          throw Error(spec.source_path + (line > 0 ? ":" + std::to_string(line) : "") + ": " + key +
                      "[" + std::to_string(i) + "]: " + e.what());
        }
      }
    }
  };
  check(spec.start_offsets, spec.start_offset_lines, "start_offsets", true);
  check(spec.goal_offsets, spec.goal_offset_lines, "goal_offsets", false);
}

}  // namespace

std::vector<SweepEpisode> expandEpisodes(const SweepSpec& spec,
                                         const std::vector<SweepWorld>& worlds) {
  checkOffsets(spec, worlds);
  std::vector<SweepEpisode> out;
  for (std::size_t w = 0; w < worlds.size(); ++w) {
    for (const std::string& planner : spec.planners)
      for (const std::string& steering : spec.steerings)
        for (const bool smooth : spec.smoothing)
          for (const std::uint64_t seed : spec.seeds)
            for (const int iterations : spec.max_iterations)
              for (const std::string& tracking : spec.tracking)
                for (const std::string& timing : spec.timing)
                  for (const std::string& realism : spec.realism)
                    for (const std::uint64_t noise_seed : spec.noise_seeds)
                      for (const PoseOffset& start : spec.start_offsets)
                        for (const PoseOffset& goal : spec.goal_offsets) {
                          EpisodeParams p;
                          p.world = worlds[w]->scenario.name;
                          p.world_file = spec.world_files.at(w);
                          p.planner = planner;
                          p.steering = steering;
                          p.smooth = smooth;
                          p.seed = seed;
                          p.max_iterations = iterations;
                          p.tracking = tracking;
                          p.timing = timing;
                          p.realism = realism;
                          p.noise_seed = noise_seed;
                          p.start_offset = start;
                          p.goal_offset = goal;
                          out.push_back({p, episodeId(p), worlds[w], &spec.tolerance});
                        }
  }
  // Every combination is checked before anything runs: a bad offset stops the sweep before it
  // writes anything.
  for (const SweepEpisode& e : out) {
    try {
      checkEpisodeRequest(episodeRequest(e.params, e.world, spec.tolerance));
    } catch (const Error& err) {
      throw Error(spec.source_path + ": " + err.what());
    }
  }
  std::sort(out.begin(), out.end(),
            [](const SweepEpisode& a, const SweepEpisode& b) { return a.id < b.id; });
  for (std::size_t i = 1; i < out.size(); ++i) {
    if (out[i].id == out[i - 1].id) {
      throw Error(spec.source_path + ": episodes '" + canonicalString(out[i - 1].params) +
                  "' and '" + canonicalString(out[i].params) + "' share the id " + out[i].id);
    }
  }
  return out;
}

}  // namespace parksim
