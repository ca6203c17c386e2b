#include "parksim/scenario/World.h"

#include <cstdint>

#include "parksim/core/Fnv1a.h"
#include "parksim/scenario/ScenarioReader.h"
#include "parksim/scenario/WorldDocument.h"

namespace parksim {
namespace {

std::string contentHash(std::string_view text, const std::vector<ScenarioOverride>& overrides,
                        const std::vector<MapLayer>& maps) {
  std::uint64_t h = fnv1a64(text);
  for (const ScenarioOverride& o : overrides) {
    h = fnv1a64("\n--set " + o.path + "=" + o.value, h);
  }
  // The maps' files are part of the world (none for a hand-written lot: its hash is its text's).
  for (const MapLayer& m : maps) h = fnv1a64("\nmap " + m.source + " " + m.content_hash, h);
  return hex16(h);
}

}  // namespace

World parseWorld(std::string_view yaml_text, const std::string& source_name,
                 const std::vector<ScenarioOverride>& overrides) {
  YAML::Node document = loadWorldDocument(yaml_text, source_name);
  for (const ScenarioOverride& o : overrides) applyOverride(document, o);
  try {
    World world = readWorldDocument(document, source_name);
    world.content_hash = contentHash(yaml_text, overrides, world.scenario.maps);
    return world;
  } catch (const Error& e) {
    rethrowNamingOverride(e, source_name, overrides);
  }
}

World loadWorld(const std::string& path, const std::vector<ScenarioOverride>& overrides) {
  return parseWorld(readWorldFile(path), path, overrides);
}

Scenario loadScenario(const std::string& path) { return loadWorld(path).scenario; }

Scenario parseScenario(std::string_view yaml_text, const std::string& source_name) {
  return parseWorld(yaml_text, source_name).scenario;
}

Scenario loadScenario(const std::string& path, const std::vector<ScenarioOverride>& overrides) {
  return loadWorld(path, overrides).scenario;
}

Scenario parseScenario(std::string_view yaml_text, const std::string& source_name,
                       const std::vector<ScenarioOverride>& overrides) {
  return parseWorld(yaml_text, source_name, overrides).scenario;
}

}  // namespace parksim
