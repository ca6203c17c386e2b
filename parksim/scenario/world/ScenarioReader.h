#pragma once
// Reads a world file (format `parksim-world/1`, described in docs/world-format.md) into an
// immutable Scenario. Bad input of any kind throws parksim::Error with a one-line message
// `<file>:<line>: <field path>: <what is wrong>` (1-based line), for example
// `worlds/x.yaml:14: obstacles[2].size[0]: must be positive, got -0.1`. A file that cannot
// be read at all has no line: `<file>: cannot open: <reason>`.

#include <cstddef>
#include <string>
#include <string_view>

#include "parksim/core/model/Scenario.h"

namespace parksim {

/// Limits checked before any work (docs/world-format.md, "Limits").
inline constexpr std::size_t kMaxWorldFileBytes = 1 << 20;  ///< 1 MiB
inline constexpr std::size_t kMaxObstacles = 10000;         ///< entries of `obstacles`
inline constexpr std::size_t kMaxParkedRobots = 10000;      ///< entries of `parked_robots`

/// Reads and validates the world file at `path`; `path` becomes Scenario::source_path and
/// prefixes every error message.
Scenario loadScenario(const std::string& path);

/// Validates world-file text already in memory. `source_name` stands in for the file name in
/// messages and in Scenario::source_path.
Scenario parseScenario(std::string_view yaml_text, const std::string& source_name);

/// Reads one pose written as the world file writes them: `[x, y, yaw_deg]`, `x, y, yaw_deg`
/// (brackets optional, for command lines), `{x: .., y: .., yaw_deg: ..}` or with `yaw_rad`.
/// The same rules as in a file apply (ranges, the radians-in-the-list-form rule); errors read
/// `<what>: <what is wrong>`, e.g. `--start[2]: must be a number, got abc`. Placement (lot,
/// obstacles) is not checked here: see placementProblem in core/model/Scenario.h.
Pose2 parsePose(std::string_view text, const std::string& what);

}  // namespace parksim
