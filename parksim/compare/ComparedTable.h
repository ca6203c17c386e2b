#pragma once
// The tables `parksim compare` reads: a sweep's output directory (DIR/results.jsonl, and
// DIR/sweep.json when present, which refuses a table of another episode-id format) or a
// results.jsonl file itself (a baseline kept in a repository).

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace parksim {

/// A table to compare, read and checked as `report` reads one (readVerifiedTable).
struct ComparedTable {
  std::vector<nlohmann::ordered_json> rows;  ///< every whole row, in file order
  /// Rows of another world content or another build than the table's first (TableOrigins):
  /// their comparison mixes two versions, so the command flags them.
  std::vector<std::string> mixes;
};

/// The table at `path`. Throws Error "<file>:<line>: ..." at a changed or malformed row, and
/// when there is no table there, it is empty, or its manifest is of another parksim.
ComparedTable readComparedTable(const std::string& path);

}  // namespace parksim
