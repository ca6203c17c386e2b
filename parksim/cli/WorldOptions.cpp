#include "parksim/cli/WorldOptions.h"

#include <cstdio>

#include "parksim/core/io/Error.h"

namespace parksim::cli {

void WorldOverrideOptions::addTo(CLI::App& sub) {
  start_option =
      sub.add_option("--start", start,
                     "replace the world's start pose: x,y,yaw in m, m, degrees (e.g. 0.3,0.6,90)");
  goal_option = sub.add_option(
      "--goal", goal, "replace the world's goal pose (goal.pose): x,y,yaw in m, m, degrees");
  sub.add_option("--set", sets,
                 "replace one world-file field, PATH=VALUE with PATH as in error messages and "
                 "VALUE in YAML (robot.wheel_radius=0.025, obstacles[1].center=[0.5,0.5]); "
                 "repeatable")
      ->allow_extra_args(false);  // one PATH=VALUE per --set: a world path after it stays one
}

std::vector<ScenarioOverride> WorldOverrideOptions::overrides() const {
  std::vector<ScenarioOverride> out;
  // "x,y,deg" is the file's [x, y, yaw_deg] list without brackets; a list or map is YAML as is.
  auto pose = [](const std::string& text) {
    const std::size_t first = text.find_first_not_of(" \t");
    const bool yaml = first != std::string::npos && (text[first] == '[' || text[first] == '{');
    return yaml ? text : "[" + text + "]";
  };
  // Given means given: an empty --start (a shell variable that was not set) is an error, not
  // the file's start.
  const auto given = [](const CLI::Option* o) { return o != nullptr && o->count() > 0; };
  if (given(start_option)) out.push_back({"start", pose(start), "--start " + start});
  if (given(goal_option)) out.push_back({"goal.pose", pose(goal), "--goal " + goal});
  for (const std::string& set : sets) {
    const std::size_t eq = set.find('=');
    if (eq == std::string::npos || eq == 0) {
      throw Error("--set " + set + ": expected PATH=VALUE, e.g. robot.wheel_radius=0.025");
    }
    out.push_back({set.substr(0, eq), set.substr(eq + 1), "--set " + set});
  }
  return out;
}

std::vector<std::string> WorldOverrideOptions::labels() const {
  std::vector<std::string> out;
  for (const ScenarioOverride& o : overrides()) out.push_back(o.label);
  return out;
}

std::shared_ptr<const World> loadWorldWith(const std::string& path,
                                           const WorldOverrideOptions& options) {
  auto world = std::make_shared<const World>(loadWorld(path, options.overrides()));
  for (const std::string& w : world->warnings) std::fprintf(stderr, "warning: %s\n", w.c_str());
  return world;
}

}  // namespace parksim::cli
