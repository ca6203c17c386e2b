#pragma once
// The JSON result files' common parts: how they are written and read, and the provenance every
// one of them records.

#include <string>

#include <nlohmann/json.hpp>

#include "parksim/core/system/Provenance.h"

namespace parksim {

/// The provenance as a JSON object (keys of provenanceFields; git_dirty a boolean), the
/// "provenance" entry of plan.json.
nlohmann::json provenanceToJson(const Provenance& provenance);

/// Writes `json` (pretty-printed, two-space indent, trailing newline). Throws Error.
void writeJsonFile(const std::string& path, const nlohmann::json& json);

/// Reads a JSON file. Throws Error naming the file.
nlohmann::json readJsonFile(const std::string& path);

/// `j` as indented text with a final newline. Strings that are not UTF-8 (names and paths
/// from input files) are written with U+FFFD in place of their bad bytes instead of failing.
std::string jsonText(const nlohmann::json& j);

}  // namespace parksim
