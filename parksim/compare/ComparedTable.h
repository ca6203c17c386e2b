#pragma once
// The tables `parksim compare` reads: a sweep's output directory (DIR/results.jsonl, and
// DIR/sweep.json when present, which refuses a table of another episode-id format) or a
// results.jsonl file itself (a baseline kept in a repository).

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace parksim {

/// The rows of the table at `path` (readResultsJsonl). Throws Error when there is no table
/// there, it is empty, or its manifest is of another parksim.
std::vector<nlohmann::ordered_json> readComparedTable(const std::string& path);

}  // namespace parksim
