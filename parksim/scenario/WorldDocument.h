#pragma once
// Internal to the scenario module: the world reader in two steps, so that a parsed document can
// be changed (ScenarioOverrides.h) before it is validated exactly like a file.

#include <string>
#include <string_view>

#include <yaml-cpp/yaml.h>

#include "parksim/core/Scenario.h"

namespace parksim {

/// The text of the world file at `path`, with loadScenario's checks (type, size) and messages.
std::string readWorldFile(const std::string& path);

/// Parses world-file text into its one YAML document. Throws Error on syntax errors, an empty
/// text or several documents.
YAML::Node loadWorldDocument(std::string_view yaml_text, const std::string& source_name);

/// Validates a world document into a Scenario (parseScenario's second half).
Scenario readWorldDocument(const YAML::Node& document, const std::string& source_name);

}  // namespace parksim
