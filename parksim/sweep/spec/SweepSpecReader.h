#pragma once
// Reads a sweep spec (format `parksim-sweep/1`, docs/sweeps.md). Bad input throws Error with
// one line `<file>:<line>: <field path>: <what is wrong>`, like the world reader, e.g.
// `study.yaml:7: planners[1]: unknown planner 'rrt*' (rrt, rrt-goal-connect, ...)`.

#include <string>
#include <string_view>

#include "parksim/sweep/spec/SweepSpec.h"

namespace parksim {

/// Reads and validates the spec at `path`. World paths are resolved against its folder.
SweepSpec loadSweepSpec(const std::string& path);

/// The same on text in memory; `source_name` names it in messages, `base_dir` resolves world
/// paths (empty: the current directory).
SweepSpec parseSweepSpec(std::string_view yaml_text, const std::string& source_name,
                         const std::string& base_dir);

}  // namespace parksim
