#pragma once
// Internal to the scenario module: the world reader in two steps, so that a parsed document can
// be changed (ScenarioOverrides.h) before it is validated exactly like a file.

#include <string>
#include <string_view>

#include <yaml-cpp/yaml.h>

#include <vector>

#include "parksim/core/io/Error.h"
#include "parksim/core/model/Scenario.h"
#include "parksim/scenario/world/ScenarioOverrides.h"
#include "parksim/scenario/world/World.h"

namespace parksim {

/// Parses world-file text into its one YAML document. Throws Error on syntax errors, an empty
/// text or several documents.
YAML::Node loadWorldDocument(std::string_view yaml_text, const std::string& source_name);

/// Validates a world document into a World (parseWorld's second half).
World readWorldDocument(const YAML::Node& document, const std::string& source_name);

class YamlField;

/// An obstacle's `kind` (wall, curb, island, box, bollard, pillar); a map entry's too.
ObstacleKind readObstacleKind(const YamlField& field);

/// Replaces the node at o.path in `document` by o.value (ScenarioOverrides.h). Throws Error
/// naming the override on a bad path or value.
void applyOverride(YAML::Node& document, const ScenarioOverride& o);

/// When o.path leads to a scalar of `document` and o.value is a scalar of the same tag (plain
/// or quoted), sets that scalar's text to o.value's, in place, and returns true: what
/// applyOverride would leave, without new nodes. False, changing nothing, otherwise.
bool replaceScalar(YAML::Node& document, const ScenarioOverride& o);

/// A reader message is "<source>:<line>: <field path>: <what>"; when the field is an
/// overridden one (or inside one), its file line is meaningless: rethrows `e` naming the
/// override instead, or unchanged.
[[noreturn]] void rethrowNamingOverride(const Error& e, const std::string& source,
                                        const std::vector<ScenarioOverride>& overrides);

}  // namespace parksim
