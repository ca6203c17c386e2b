#pragma once
// A running sweep's results table: DIR/results.jsonl and DIR/results.csv (ResultsFile.h),
// appended one finished episode at a time, each row sealed (RowSeal.h).
//
// Crash safety: each row is one write() per file to a file opened O_APPEND, so a killed process
// leaves whole rows (the kernel keeps what write() returned); fdatasync runs at most once per
// sync_interval_s and on close, for machine crashes. A row whose write fails (a full disk, a
// file-size limit) is taken back from both files (ftruncate needs no space), so the files hold
// whole rows and agree after any failed write. Opening a table repairs what a kill in the middle
// of a write can still leave: a last line without its newline is cut off, and results.csv is
// rebuilt from results.jsonl (the reference) when it lacks rows at its end.
//
// Integrity: opening reads every row and refuses (Error naming the file and line) a row whose
// seal does not match its content, a line of results.csv that is not the rendering of its
// results.jsonl row, and rows of another world content or another build than the expected ones
// (TableExpectations): a resumed sweep never mixes two versions of a world or of parksim.
// One writer: DIR/.results.lock is held (flock) while the table is open, so a second sweep into
// the same DIR fails at once instead of interleaving rows.

#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "parksim/results/tables/ResultsFile.h"

namespace parksim {

/// What the rows already in a table must agree with to be resumed.
struct TableExpectations {
  /// World name -> World::content_hash of the world file this sweep read. Rows of these worlds must
  /// carry the same world_hash; rows of other worlds (an edited spec) are kept as they are.
  std::map<std::string, std::string> world_hashes;
  /// rowWriter of this build; empty: rows of any build are accepted.
  std::string writer;
  /// The set columns the sweep writes (its set: paths, EpisodeRecord.h's isSetKey): results.csv
  /// gets a column for each, and for every set key of the rows already in.
  std::vector<std::string> set_columns;
};

/// The lock file of DIR's table, held by the sweep writing it.
std::string resultsLockPath(const std::string& dir);

/// True when a sweep holds DIR's table open now (its lock is taken).
bool resultsTableBusy(const std::string& dir);

class ResultsTable {
 public:
  /// Opens (creating, or repairing as described above) DIR/results.jsonl and DIR/results.csv.
  /// results.csv is rebuilt with more columns when the sweep sets paths it has no column for.
  /// Throws Error when they cannot be opened, another sweep holds them, results.csv has another
  /// header (another parksim version's columns), or a row fails the checks above.
  explicit ResultsTable(const std::string& dir, const TableExpectations& expect = {},
                        double sync_interval_s = 1.0);
  ~ResultsTable();
  ResultsTable(const ResultsTable&) = delete;
  ResultsTable& operator=(const ResultsTable&) = delete;

  /// Ids already in the table, with whether each met its tolerance (met_tolerance).
  const std::map<std::string, bool>& done() const { return done_; }

  /// What opening repaired, one line each ("<file>: ..."), for the command to print.
  const std::vector<std::string>& repairs() const { return repairs_; }

  /// Seals and appends one row (it must have episode_id and met_tolerance, and no
  /// row_checksum). Throws Error on a failed write, after taking the row back from both files.
  void append(const nlohmann::ordered_json& row);

  /// fdatasync both files now.
  void sync();

 private:
  void open(const std::string& dir, const TableExpectations& expect);

  std::string jsonl_path_;
  std::string csv_path_;
  std::vector<std::string> set_columns_;  // results.csv's set columns, sorted
  std::vector<std::string> columns_;      // all of results.csv's
  int lock_fd_ = -1;
  int jsonl_fd_ = -1;
  int csv_fd_ = -1;
  long long jsonl_size_ = 0;  // bytes of whole rows: where a failed append is cut back to
  long long csv_size_ = 0;
  double sync_interval_s_;
  double last_sync_s_ = 0.0;
  std::map<std::string, bool> done_;
  std::vector<std::string> repairs_;
};

}  // namespace parksim
