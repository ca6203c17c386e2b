#include "parksim/scenario/World.h"

#include "parksim/scenario/ScenarioReader.h"
#include "parksim/scenario/WorldDocument.h"

namespace parksim {

World parseWorld(std::string_view yaml_text, const std::string& source_name,
                 const std::vector<ScenarioOverride>& overrides) {
  YAML::Node document = loadWorldDocument(yaml_text, source_name);
  for (const ScenarioOverride& o : overrides) applyOverride(document, o);
  try {
    return readWorldDocument(document, source_name);
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
