#pragma once
// `parksim verify DIR`: checks a results table without changing it, and lists every problem
// (not just the first, as the readers do): rows whose seal does not match their content,
// lines that are not rows, lines of results.csv that are not the rendering of their
// results.jsonl row, an episode twice in one table, rows of other world contents or builds.
// Which tables a sweep directory holds (its shards) is the sweep's: sweep/shards/Merge.h's
// verifyResults.

#include <cstddef>
#include <string>
#include <vector>

namespace parksim {

struct TableVerification {
  std::vector<std::string> tables;  ///< the results.jsonl files checked
  std::size_t rows = 0;             ///< rows that passed every check
  /// One line each, "<file>:<line>: <what>" (or "<file>: <what>"), in file order.
  std::vector<std::string> problems;
  /// Problems beyond those listed (per table, after `max_listed`).
  std::size_t unlisted = 0;
  /// What is not a problem but worth knowing: a torn last row or a results.csv one row behind
  /// (a killed sweep; the next sweep repairs both), episodes of sweep.json not in the table.
  std::vector<std::string> notes;
  bool ok() const { return problems.empty() && unlisted == 0; }
};

/// Checks DIR/results.jsonl and DIR/results.csv into `v` (its tables, rows, problems, notes).
/// `expected_ids` (sweep.json's episode ids, when given) are the episodes the table should
/// hold: those it lacks are a note. At most `max_listed` problems of this table are listed, the
/// rest counted in `v.unlisted`.
void verifyTable(const std::string& dir, const std::vector<std::string>* expected_ids,
                 std::size_t max_listed, TableVerification& v);

}  // namespace parksim
