#pragma once
// The entries of a sweep spec's planners: and controllers: axes, and its plugins: list
// (docs/your-code.md, "In a sweep"): what SweepSpecReader.cpp reads for them.

#include <string>
#include <vector>

#include "parksim/scenario/yaml/YamlField.h"
#include "parksim/sweep/spec/SweepSpec.h"

namespace parksim {

/// The axis's items (a name, {name: N, params: {...}}, or {command: [...], params: {...}}) as
/// choices, each once; `what` is "planner" or "controller" for messages. Programs given as
/// paths are resolved against `base_dir`.
std::vector<ComponentChoice> componentsAxis(const std::vector<YamlField>& items,
                                            const std::string& base_dir, const char* what);

/// plugins: paths of shared libraries, resolved against `base_dir`, each once.
void readPlugins(const YamlField& field, const std::string& base_dir, SweepSpec& spec);

}  // namespace parksim
