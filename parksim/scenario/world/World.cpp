#include "parksim/scenario/world/World.h"

#include <cstdint>

#include "parksim/core/io/Fnv1a.h"
#include "parksim/scenario/world/ScenarioReader.h"
#include "parksim/scenario/world/WorldDocument.h"

namespace parksim {
namespace {

// `text_hash` is fnv1a64 of the file's text.
std::string contentHash(std::uint64_t text_hash, const std::vector<ScenarioOverride>& overrides,
                        const std::vector<MapLayer>& maps) {
  std::uint64_t h = text_hash;
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
    world.content_hash = contentHash(fnv1a64(yaml_text), overrides, world.scenario.maps);
    return world;
  } catch (const Error& e) {
    rethrowNamingOverride(e, source_name, overrides);
  }
}

struct WorldFile::Parsed {
  std::string text;
  std::string source;
  YAML::Node document;
  std::uint64_t text_hash = 0;  // of `text`, once: World::content_hash starts from it
  // The document with the last read's overrides applied, and their paths: the next read with
  // the same paths and scalar values sets them in place instead of cloning the document (a
  // sweep's samples differ in their values, not their paths). A clone and its freeing were
  // two fifths of a read.
  YAML::Node scratch;
  std::vector<std::string> scratch_paths;
};

WorldFile::WorldFile(std::string text, std::string source_name)
    : parsed_(std::make_unique<Parsed>()) {
  parsed_->document = loadWorldDocument(text, source_name);
  parsed_->text_hash = fnv1a64(text);
  parsed_->text = std::move(text);
  parsed_->source = std::move(source_name);
}

WorldFile::~WorldFile() = default;

WorldFile::WorldFile(const WorldFile& other)
    : parsed_(std::make_unique<Parsed>(Parsed{other.parsed_->text,
                                              other.parsed_->source,
                                              YAML::Clone(other.parsed_->document),
                                              other.parsed_->text_hash,
                                              {},
                                              {}})) {}

World WorldFile::read(const std::vector<ScenarioOverride>& overrides) const {
  Parsed& p = *parsed_;
  YAML::Node document = p.document;
  if (!overrides.empty()) {
    bool same_paths = p.scratch_paths.size() == overrides.size();
    for (std::size_t i = 0; same_paths && i < overrides.size(); ++i) {
      same_paths = p.scratch_paths[i] == overrides[i].path;
    }
    bool in_place = same_paths;
    for (std::size_t i = 0; in_place && i < overrides.size(); ++i) {
      in_place = replaceScalar(p.scratch, overrides[i]);
    }
    if (!in_place) {
      // Overrides change the document: a copy of it (a clone is a fraction of a parse).
      p.scratch.reset();
      p.scratch_paths.clear();
      YAML::Node copy = YAML::Clone(p.document);
      for (const ScenarioOverride& o : overrides) applyOverride(copy, o);
      p.scratch.reset(copy);
      for (const ScenarioOverride& o : overrides) p.scratch_paths.push_back(o.path);
    }
    document.reset(p.scratch);
  }
  try {
    World world = readWorldDocument(document, parsed_->source);
    world.content_hash = contentHash(parsed_->text_hash, overrides, world.scenario.maps);
    return world;
  } catch (const Error& e) {
    rethrowNamingOverride(e, parsed_->source, overrides);
  }
}

const std::string& WorldFile::text() const { return parsed_->text; }
const std::string& WorldFile::sourceName() const { return parsed_->source; }

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
