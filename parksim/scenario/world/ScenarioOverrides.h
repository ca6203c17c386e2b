#pragma once
// A world file with some of its fields replaced, e.g. from the command line (`--set
// robot.wheel_radius=0.025`, `--start 0.3,0.6,90`). The replacements are made in the parsed
// YAML document before the reader validates it, so an overridden value passes exactly the checks
// a value in the file does; a message about it names the override instead of a file line:
// `--set robot.wheel_radius=-1: robot.wheel_radius: must be positive, got -1`.

#include <string>
#include <string_view>
#include <vector>

#include "parksim/core/model/Scenario.h"

namespace parksim {

struct ScenarioOverride {
  /// Field path as in the reader's messages: keys joined by '.', list items as [i], e.g.
  /// "robot.wheel_radius", "obstacles[2].center", "goal.pose". Missing map keys are created
  /// (so a section the file leaves out can be set); list items must exist.
  std::string path;
  /// YAML text of the new value: "0.025", "[0.3, 0.6, 90]", "{x: 0.3, y: 0.6, yaw_deg: 90}".
  std::string value;
  /// Names the override in messages, e.g. "--set robot.wheel_radius=0.025".
  std::string label;
};

/// Reads the world file at `path`, applies `overrides` in order, then validates as
/// loadScenario does. Throws Error; messages about an overridden field start with its label.
Scenario loadScenario(const std::string& path, const std::vector<ScenarioOverride>& overrides);

/// The same for text in memory (`source_name` as in parseScenario).
Scenario parseScenario(std::string_view yaml_text, const std::string& source_name,
                       const std::vector<ScenarioOverride>& overrides);

}  // namespace parksim
