#include "parksim/sweep/spec/EpisodeExpansion.h"

#include "parksim/usercode/PluginLoader.h"

#include <algorithm>
#include <atomic>
#include <exception>
#include <set>
#include <thread>

#include "parksim/core/io/Error.h"
#include "parksim/pipeline/EpisodeSettings.h"
#include "parksim/sweep/spec/EpisodeSetup.h"
#include "parksim/sweep/spec/SetValues.h"

namespace parksim {

std::vector<SweepWorld> loadSweepWorlds(const SweepSpec& spec) {
  std::vector<SweepWorld> worlds;
  for (std::size_t i = 0; i < spec.world_paths.size(); ++i) {
    const std::string& path = spec.world_paths[i];
    worlds.push_back(std::make_shared<const SweepWorldFile>(path, readWorldFile(path)));
    for (std::size_t j = 0; j < i; ++j) {
      if (worlds[j]->world.scenario.name == worlds[i]->world.scenario.name) {
        throw Error(spec.source_path + ":" + std::to_string(spec.worlds_line) +
                    ": worlds: " + spec.world_files[j] + " and " + spec.world_files[i] +
                    " both name their scenario '" + worlds[i]->world.scenario.name +
                    "' (episode ids use the name; rename one)");
      }
    }
  }
  return worlds;
}

SweepWorldFile::SweepWorldFile(std::string path_in, std::string text)
    : path(std::move(path_in)), file(std::move(text), path), world(file.read()) {}

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
          (void)episodeRequest(p, episodeWorld(p, world), spec.tolerance);
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

// A message about a world read with set: values, at the spec's line of the value it names
// ("set: PATH=VALUE: ..."), else with the episode's set: values (and sample) at the line of the
// first of their axes.
Error setError(const SweepSpec& spec, const EpisodeParams& p, const SweepWorld& world,
               const std::string& what) {
  for (const SetAxis& axis : spec.set) {
    if (what.rfind("set: " + axis.path + "=", 0) == 0) {
      return Error(spec.source_path + ":" + std::to_string(axis.line) + ": " + what +
                   (spec.world_files.size() > 1 ? " (in " + world->path + ")" : ""));
    }
  }
  std::string values;
  int line = 0;
  for (const SetAxis& axis : spec.set) {
    const ParamMap& of = axis.target() == SetAxis::Target::kWorld     ? p.world_set
                         : axis.target() == SetAxis::Target::kPlanner ? p.planner_params
                                                                      : p.controller_params;
    const auto it =
        of.find(axis.target() == SetAxis::Target::kWorld ? axis.path : axis.parameterName());
    if (it == of.end()) continue;
    if (values.empty()) line = axis.line;
    values += (values.empty() ? "" : ", ") + axis.path + "=" + it->second;
  }
  return Error(spec.source_path + (line > 0 ? ":" + std::to_string(line) : std::string()) +
               ": set: " + values +
               (p.sample ? " (sample " + std::to_string(*p.sample) + ")" : "") + ": " + what);
}

// A message about an episode that is not a valid request: at the spec, with its set: values.
Error episodeError(const SweepSpec& spec, const EpisodeParams& p, const SweepWorld& world,
                   const std::string& what) {
  if (spec.set.empty()) return Error(spec.source_path + ": " + what);
  return setError(spec, p, world, what);
}

// Each grid value of each world-value axis on each world, alone, as `--set PATH=VALUE` checks
// it: a bad path or value is named by its line before any combination is tried.
void checkSetValues(const SweepSpec& spec, const std::vector<SweepWorld>& worlds) {
  for (const SetAxis& axis : spec.set) {
    if (axis.target() != SetAxis::Target::kWorld) continue;
    for (const std::string& value : axis.values) {
      EpisodeParams p;
      p.world_set[axis.path] = value;
      for (const SweepWorld& world : worlds) {
        try {
          (void)episodeWorld(p, world);
        } catch (const Error& e) {
          throw setError(spec, p, world, e.what());
        }
      }
    }
  }
}

// Every planner and controller of the axes is registered and takes its own parameters and each
// value of the set: axes' planner.NAME and controller.NAME, each refused at its line in the
// spec; each made once, a plugin's in one watched process (ComponentCheck.h). What is made is
// added to `made`: the combinations of several axes are made when the episodes have expanded.
void checkComponents(const SweepSpec& spec, const Components& components,
                     const ComponentCheckDef& def, std::set<ComponentParams>& made) {
  const auto at = [&](int line, const std::string& what) {
    return Error(spec.source_path + (line > 0 ? ":" + std::to_string(line) : std::string()) + ": " +
                 what);
  };
  std::vector<ComponentParams> list;
  std::vector<std::pair<int, std::string>> where;  // the spec's line and what it names
  const auto add = [&](ComponentParams c, int line, std::string prefix) {
    if (!made.insert(c).second) return;
    list.push_back(std::move(c));
    where.emplace_back(line, std::move(prefix));
  };
  const auto choices = [&](const std::vector<ComponentChoice>& entries, ComponentParams::Kind kind,
                           SetAxis::Target target) {
    for (const ComponentChoice& c : entries) {
      add({kind, c.name, c.params}, c.line, c.path.empty() ? std::string() : c.path + ": ");
      for (const SetAxis& axis : spec.set) {
        if (axis.target() != target) continue;
        if (c.params.count(axis.parameterName()) > 0) {
          throw at(axis.line, axis.path + ": " + c.name + "'s entry gives it already");
        }
        for (const std::string& value : axis.values) {
          ParamMap params = c.params;
          params[axis.parameterName()] = value;
          add({kind, c.name, std::move(params)}, axis.line, axis.path + "=" + value + ": ");
        }
      }
    }
  };
  choices(spec.planners, ComponentParams::Kind::kPlanner, SetAxis::Target::kPlanner);
  choices(spec.controllers, ComponentParams::Kind::kController, SetAxis::Target::kController);
  if (const std::optional<ComponentRefusal> refused =
          firstRefusedComponent(components, list, def)) {
    const auto& [line, prefix] = where[refused->index];
    throw at(line, prefix + refused->message);
  }
}

// The set: part of an episode: world values, planner and controller parameters, the sample.
struct SetCombination {
  ParamMap world_set;
  ParamMap planner_params;
  ParamMap controller_params;
  std::optional<std::uint64_t> sample;
};

void assign(const SetAxis& axis, const std::string& value, SetCombination& c) {
  switch (axis.target()) {
    case SetAxis::Target::kWorld: c.world_set[axis.path] = value; break;
    case SetAxis::Target::kPlanner: c.planner_params[axis.parameterName()] = value; break;
    case SetAxis::Target::kController: c.controller_params[axis.parameterName()] = value; break;
  }
}

// The grid of the set: axes with lists (their product), each with every sample's draws.
std::vector<SetCombination> setCombinations(const SweepSpec& spec) {
  std::vector<SetCombination> grid(1);
  for (const SetAxis& axis : spec.set) {
    if (axis.distribution) continue;
    std::vector<SetCombination> next;
    next.reserve(grid.size() * axis.values.size());
    for (const SetCombination& c : grid) {
      for (const std::string& value : axis.values) {
        next.push_back(c);
        assign(axis, value, next.back());
      }
    }
    grid = std::move(next);
  }
  if (!spec.samples) return grid;
  std::vector<SetCombination> all;
  all.reserve(grid.size() * spec.samples->count);
  for (const SetCombination& c : grid) {
    for (std::uint64_t i = 0; i < spec.samples->count; ++i) {
      all.push_back(c);
      all.back().sample = i;
      for (const SetAxis& axis : spec.set) {
        if (axis.distribution) {
          assign(axis, drawSetValue(*axis.distribution, *spec.samples, i, axis.path), all.back());
        }
      }
    }
  }
  return all;
}

}  // namespace

namespace {

// What the episodes of one task make (a planner, a controller, with parameters), each with the
// first episode that makes it: checked once for all, on the calling thread, when every task
// has expanded.
using FirstUses = std::vector<std::pair<ComponentParams, EpisodeParams>>;

// The episodes of one world and one set: combination, each checked as a request (but for the
// making of its components, added to `uses`). The combination's world is read once for all of
// them (from `own`, this thread's copy of the file) and then let go: a sampled spec has one per
// sample.
std::vector<SweepEpisode> expandCombination(const SweepSpec& spec, const SweepWorld& file,
                                            const std::string& world_file,
                                            const SetCombination& set, const WorldFile& own,
                                            const std::shared_ptr<const Components>& components,
                                            FirstUses& uses) {
  std::set<ComponentParams> used;
  EpisodeParams base;
  base.world = file->world.scenario.name;
  base.world_file = world_file;
  base.sample = set.sample;
  base.world_set = set.world_set;
  base.planner_params = set.planner_params;
  base.controller_params = set.controller_params;
  std::shared_ptr<const World> world;
  try {
    world = episodeWorld(base, file, own);
  } catch (const Error& e) {
    throw setError(spec, base, file, e.what());
  }
  std::vector<SweepEpisode> out;
  for (const ComponentChoice& planner : spec.planners)
    for (const ComponentChoice& controller : spec.controllers)
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
                          EpisodeParams p = base;
                          p.planner = planner.name;
                          p.planner_params.insert(planner.params.begin(), planner.params.end());
                          p.controller = controller.name;
                          p.controller_params.insert(controller.params.begin(),
                                                     controller.params.end());
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
                          // Every combination is checked before anything runs: a bad offset
                          // stops the sweep before it writes anything.
                          try {
                            for (ComponentParams& c : checkEpisodeValues(
                                     episodeRequest(p, world, spec.tolerance, components))) {
                              if (used.insert(c).second) uses.emplace_back(std::move(c), p);
                            }
                          } catch (const Error& err) {
                            throw episodeError(spec, p, file, err.what());
                          }
                          std::string id = episodeId(p);
                          out.push_back(
                              {std::move(p), std::move(id), file, components, &spec.tolerance});
                        }
  return out;
}

// The planners and controllers the episodes make that checkComponents did not (several axes'
// values together, sampled values), each once, in the order of the episodes' tasks: a refusal
// is reported as the first episode that makes it would report it.
void checkUses(const SweepSpec& spec, const std::vector<SweepWorld>& worlds,
               const Components& components, const ComponentCheckDef& check,
               const std::vector<FirstUses>& uses, std::size_t combinations,
               std::set<ComponentParams>& made) {
  std::vector<ComponentParams> list;
  std::vector<std::pair<const EpisodeParams*, std::size_t>> first;  // episode, world index
  for (std::size_t t = 0; t < uses.size(); ++t) {
    for (const auto& [c, p] : uses[t]) {
      if (!made.insert(c).second) continue;
      list.push_back(c);
      first.emplace_back(&p, t / combinations);
    }
  }
  if (const std::optional<ComponentRefusal> refused =
          firstRefusedComponent(components, list, check)) {
    const auto& [p, w] = first[refused->index];
    throw episodeError(spec, *p, worlds[w], refused->message);
  }
}

}  // namespace

std::shared_ptr<const Components> loadSweepComponents(const SweepSpec& spec,
                                                      const Components* extra) {
  if (spec.plugin_paths.empty() && extra == nullptr) return builtInComponents();
  auto components = std::make_shared<Components>();
  for (std::size_t i = 0; i < spec.plugin_paths.size(); ++i) {
    try {
      loadPlugin(*components, spec.plugin_paths[i]);
    } catch (const Error& e) {
      throw Error(spec.source_path + ":" + std::to_string(spec.plugins_line) +
                  ": plugins: " + e.what());
    }
  }
  if (extra != nullptr) {
    for (const PlannerEntry& e : extra->planners.entries()) {
      if (!components->planners.tryFind(e.info.name)) components->planners.add(e, e.info.plugin);
    }
    for (const ControllerEntry& e : extra->controllers.entries()) {
      if (!components->controllers.tryFind(e.info.name)) {
        components->controllers.add(e, e.info.plugin);
      }
    }
  }
  return components;
}

std::vector<SweepEpisode> expandEpisodes(const SweepSpec& spec,
                                         const std::vector<SweepWorld>& worlds,
                                         const std::shared_ptr<const Components>& components,
                                         const ComponentCheckDef& check) {
  checkOffsets(spec, worlds);
  checkSetValues(spec, worlds);
  std::set<ComponentParams> made;
  checkComponents(spec, *components, check, made);
  const std::vector<SetCombination> combinations = setCombinations(spec);
  // World x combination, expanded on every core: each combination with world values reads its
  // world again (10,000 samples of the study's lot: 10,000 reads).
  const std::size_t tasks = worlds.size() * combinations.size();
  std::vector<std::vector<SweepEpisode>> parts(tasks);
  std::vector<FirstUses> uses(tasks);
  std::atomic<std::size_t> next{0};
  std::atomic<std::size_t> first_error{tasks};
  std::vector<std::exception_ptr> errors(tasks);
  const auto work = [&] {
    std::vector<std::unique_ptr<WorldFile>> own(worlds.size());
    for (;;) {
      const std::size_t t = next.fetch_add(1);
      if (t >= tasks || t > first_error.load()) return;
      const std::size_t w = t / combinations.size();
      if (!own[w]) {
        const std::lock_guard<std::mutex> lock(worlds[w]->mutex);
        own[w] = std::make_unique<WorldFile>(worlds[w]->file);
      }
      try {
        parts[t] =
            expandCombination(spec, worlds[w], spec.world_files.at(w),
                              combinations[t % combinations.size()], *own[w], components, uses[t]);
      } catch (...) {
        errors[t] = std::current_exception();
        std::size_t seen = first_error.load();
        while (t < seen && !first_error.compare_exchange_weak(seen, t)) {
        }
      }
    }
  };
  const std::size_t threads = std::clamp<std::size_t>(std::thread::hardware_concurrency(), 1,
                                                      std::max<std::size_t>(tasks, 1));
  std::vector<std::thread> pool;
  for (std::size_t i = 1; i < threads; ++i) pool.emplace_back(work);
  work();
  for (std::thread& t : pool) t.join();
  // The first error in the serial order, whichever thread met it first.
  if (first_error.load() < tasks) std::rethrow_exception(errors[first_error.load()]);
  checkUses(spec, worlds, *components, check, uses, combinations.size(), made);
  std::vector<SweepEpisode> out;
  std::size_t total = 0;
  for (const auto& part : parts) total += part.size();
  out.reserve(total);
  for (auto& part : parts) {
    for (SweepEpisode& e : part) out.push_back(std::move(e));
    std::vector<SweepEpisode>().swap(part);
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
