#pragma once
// A world file read once, whole: the immutable Scenario (lot, obstacles, robot, start, goal,
// physics) and the file's realism: and tolerance: sections. Every front-end loads worlds through
// loadWorld, so a file is parsed and validated once per command, with or without overrides.

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "parksim/core/model/Scenario.h"
#include "parksim/scenario/world/RealismReader.h"
#include "parksim/scenario/world/ScenarioOverrides.h"

namespace parksim {

struct World {
  Scenario scenario;
  /// The file's realism: and tolerance: sections (each flagged when present).
  WorldRealism sections;
  /// 16 hex digits of the 64-bit FNV-1a hash of the text read (the file's bytes), followed by
  /// each override's path and value: two worlds with one name but other contents differ here.
  /// A sweep's results rows carry it (world_hash) so that an edited world file is noticed.
  std::string content_hash;
  /// What was read but ignored, one line each naming the file, line and key (a ROS map YAML's
  /// key that map_server does not read): the front ends print them as warnings.
  std::vector<std::string> warnings;
};

/// Reads the world file at `path`, applies `overrides` in order and validates the result as a
/// file (ScenarioReader.h's messages; an overridden field is named by its override's label).
World loadWorld(const std::string& path, const std::vector<ScenarioOverride>& overrides = {});

/// The text of the world file at `path`, with loadWorld's checks (a regular file within the
/// size limit) and messages: for a reader that parses it more than once (a sweep applies its
/// set: values to it per episode).
std::string readWorldFile(const std::string& path);

/// The same for world-file text in memory; `source_name` stands in for the file name.
World parseWorld(std::string_view yaml_text, const std::string& source_name,
                 const std::vector<ScenarioOverride>& overrides = {});

/// A world file's text parsed once, to be read many times with other overrides (a sweep applies
/// its set: values per episode): read(overrides) is parseWorld(text, source_name, overrides)
/// without parsing the text again (a parse of the study's lot costs ~5 times a read). One
/// object is not for use from several threads at once; copies share nothing.
class WorldFile {
 public:
  /// Throws Error as parseWorld does on a syntax error.
  WorldFile(std::string text, std::string source_name);
  ~WorldFile();
  WorldFile(const WorldFile& other);
  WorldFile& operator=(const WorldFile&) = delete;

  World read(const std::vector<ScenarioOverride>& overrides = {}) const;
  const std::string& text() const;
  const std::string& sourceName() const;

 private:
  struct Parsed;
  std::unique_ptr<Parsed> parsed_;
};

}  // namespace parksim
