#pragma once
// Reads a world file (format `parksim-world/1`, described in docs/world-format.md) into an
// immutable Scenario. Bad input of any kind throws parksim::Error with a one-line message
// `<file>:<line>: <field path>: <what is wrong>` (1-based line), for example
// `worlds/x.yaml:14: obstacles[2].size[0]: must be positive, got -0.1`. A file that cannot
// be read at all has no line: `<file>: cannot open: <reason>`.

#include <string>
#include <string_view>

#include "parksim/core/Scenario.h"

namespace parksim {

/// Reads and validates the world file at `path`; `path` becomes Scenario::source_path and
/// prefixes every error message.
Scenario loadScenario(const std::string& path);

/// Validates world-file text already in memory. `source_name` stands in for the file name in
/// messages and in Scenario::source_path.
Scenario parseScenario(std::string_view yaml_text, const std::string& source_name);

}  // namespace parksim
