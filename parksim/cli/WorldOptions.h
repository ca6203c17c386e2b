#pragma once
// `--start x,y,deg`, `--goal x,y,deg` and `--set path.to.field=value` on the commands that read
// a world (plan, run, render): the world file with some fields replaced, validated exactly like
// the file (parksim/scenario/world/ScenarioOverrides.h).

#include <memory>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "parksim/core/model/Scenario.h"
#include "parksim/scenario/world/ScenarioOverrides.h"
#include "parksim/scenario/world/World.h"

namespace parksim::cli {

struct WorldOverrideOptions {
  std::string start;              ///< "x,y,deg", when start_option was given
  std::string goal;               ///< "x,y,deg", when goal_option was given
  std::vector<std::string> sets;  ///< "path.to.field=value", applied in order after start, goal

  CLI::Option* start_option = nullptr;  ///< set by addTo
  CLI::Option* goal_option = nullptr;

  /// Registers --start, --goal and --set on `sub`.
  void addTo(CLI::App& sub);
  /// The overrides these options ask for. Throws Error on a --set without '='.
  std::vector<ScenarioOverride> overrides() const;
  /// One label per override ("--set robot.height=0.05"), for result files.
  std::vector<std::string> labels() const;
};

/// The world file at `path` with the options' overrides applied (scenario/world/World.h's
/// loadWorld); its warnings (World::warnings) printed to stderr, one "warning: " line each.
std::shared_ptr<const World> loadWorldWith(const std::string& path,
                                           const WorldOverrideOptions& options);

}  // namespace parksim::cli
