#pragma once
// A world file read once, whole: the immutable Scenario (lot, obstacles, robot, start, goal,
// physics) and the file's realism: and tolerance: sections. Every front-end loads worlds through
// loadWorld, so a file is parsed and validated once per command, with or without overrides.

#include <string>
#include <string_view>
#include <vector>

#include "parksim/core/Scenario.h"
#include "parksim/scenario/RealismReader.h"
#include "parksim/scenario/ScenarioOverrides.h"

namespace parksim {

struct World {
  Scenario scenario;
  /// The file's realism: and tolerance: sections (each flagged when present).
  WorldRealism sections;
  /// 16 hex digits of the 64-bit FNV-1a hash of the text read (the file's bytes), followed by
  /// each override's path and value: two worlds with one name but other contents differ here.
  /// A sweep's results rows carry it (world_hash) so that an edited world file is noticed.
  std::string content_hash;
};

/// Reads the world file at `path`, applies `overrides` in order and validates the result as a
/// file (ScenarioReader.h's messages; an overridden field is named by its override's label).
World loadWorld(const std::string& path, const std::vector<ScenarioOverride>& overrides = {});

/// The same for world-file text in memory; `source_name` stands in for the file name.
World parseWorld(std::string_view yaml_text, const std::string& source_name,
                 const std::vector<ScenarioOverride>& overrides = {});

}  // namespace parksim
