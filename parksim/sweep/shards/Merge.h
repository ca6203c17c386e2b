#pragma once
// Merges results tables (one per shard, machine or run) into one: every episode once, sorted
// by episode id, whatever order the sources come in. Idempotent: merging a merged table with
// its sources again gives the same table.
//
// Rows are read one line at a time and checked (ResultsFile.h: every seal, every key type); a
// merge keeps, per episode, where its row is (file, offset) and a hash of its content, not the
// row, so 100,000 rows merge in a few seconds and a few tens of MB. The merged table copies
// each row's line from its source as written (seal included).

#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "parksim/results/tables/TableVerify.h"

namespace parksim {

/// Where one merged row is.
struct MergedRow {
  std::string id;            ///< episode_id
  std::size_t source = 0;    ///< index into MergeResult::sources
  std::uint64_t offset = 0;  ///< of the row's line in that file
  std::size_t length = 0;    ///< of the line, without its newline
};

struct MergeResult {
  std::vector<std::string> sources;  ///< the results.jsonl files read, in order
  std::vector<MergedRow> rows;       ///< one per episode id, ascending id
  /// Ids the sources' manifests (sweep.json) expect; 0 when no source has one.
  std::size_t expected = 0;
  std::vector<std::string> missing;     ///< expected, but in no source
  std::vector<std::string> duplicated;  ///< in more than one row, all alike (timing aside)
  /// In more than one row with different content (timing aside): the first source's row is
  /// kept. The same binary gives the same row, so this means different builds or worlds.
  std::vector<std::string> conflicting;
  std::vector<std::string> unexpected;  ///< in a table but in no manifest (when there are any)
  /// The sources mix world contents or builds (TableOrigins::mixes), one line each.
  std::vector<std::string> mixes;
  /// The set keys of the rows (results.csv's set columns), sorted.
  std::vector<std::string> set_columns;
};

/// The source directories `parksim merge DIR` reads: DIR/shards/* that hold results.jsonl,
/// sorted by shard number; DIR itself when it has no shards folder.
std::vector<std::string> mergeSources(const std::string& dir);

/// `parksim verify DIR`: checks DIR's results table and, for a Slurm sweep, the table of every
/// DIR/shards/* (results/TableVerify.h); the episodes of DIR/sweep.json a table lacks are a
/// note. At most `max_listed` problems are listed per table. Throws Error when DIR holds no
/// results table at all.
TableVerification verifyResults(const std::string& dir, std::size_t max_listed = 20);

/// Reads DIR/results.jsonl (and DIR/sweep.json when present) of every source, and the
/// manifests of `manifest_dirs` (a Slurm sweep's top folder). A source without results.jsonl
/// counts as empty when some manifest says what it should have held; otherwise, like a
/// malformed file or a changed row (Error naming the file and line), it throws Error.
MergeResult mergeResults(const std::vector<std::string>& source_dirs,
                         const std::vector<std::string>& manifest_dirs = {});

/// Writes the merged rows to DIR/results.jsonl and DIR/results.csv, both whole or neither
/// (ResultsTableWriter); each row's line is read again from its source and checked. The
/// sources may include DIR itself.
void writeMergedTable(const std::string& dir, const MergeResult& merged);

/// The merged rows, parsed, in order (for small tables: ~8 KB of memory per row).
std::vector<nlohmann::ordered_json> mergedRows(const MergeResult& merged);

}  // namespace parksim
