#pragma once
// Merges results tables (one per shard, machine or run) into one: every episode once, sorted
// by episode id, whatever order the sources come in. Idempotent: merging a merged table with
// its sources again gives the same table.

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace parksim {

struct MergeResult {
  std::vector<nlohmann::ordered_json> rows;  ///< one per episode id, ascending id
  /// Ids the sources' manifests (sweep.json) expect; 0 when no source has one.
  std::size_t expected = 0;
  std::vector<std::string> missing;     ///< expected, but in no source
  std::vector<std::string> duplicated;  ///< in more than one row, all alike (timing aside)
  /// In more than one row with different content (timing aside): the first source's row is
  /// kept. The same binary gives the same row, so this means different builds or worlds.
  std::vector<std::string> conflicting;
  std::vector<std::string> unexpected;  ///< in a table but in no manifest (when there are any)
};

/// The source directories `parksim merge DIR` reads: DIR/shards/* that hold results.jsonl,
/// sorted by shard number; DIR itself when it has no shards folder.
std::vector<std::string> mergeSources(const std::string& dir);

/// Reads DIR/results.jsonl (and DIR/sweep.json when present) of every source, and the
/// manifests of `manifest_dirs` (a Slurm sweep's top folder). A source without results.jsonl
/// counts as empty when some manifest says what it should have held; otherwise, like a
/// malformed file, it throws Error.
MergeResult mergeResults(const std::vector<std::string>& source_dirs,
                         const std::vector<std::string>& manifest_dirs = {});

}  // namespace parksim
