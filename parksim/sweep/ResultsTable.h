#pragma once
// A sweep's results table: DIR/results.jsonl (one JSON object per line, every key) and
// DIR/results.csv (the fixed columns of resultColumns(), one row per episode), appended one
// finished episode at a time.
//
// Crash safety: each row is one write() per file to a file opened O_APPEND, so a killed process
// leaves whole rows (the kernel keeps what write() returned); fdatasync runs at most once per
// sync_interval_s and on close, for machine crashes. Opening a table repairs what a crash in the
// middle of a write can still leave: a last line without its newline (or one that does not
// parse) is cut off, and results.csv is rebuilt from results.jsonl when the two disagree
// (results.jsonl is written first and is the reference).

#include <cstdint>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

namespace parksim {

/// results.csv's columns, in order: episode_id, the parameters, the outcome, plan statistics,
/// simulation metrics, timing and provenance. Keys a row lacks (a failed plan has no
/// simulation) are empty cells. results.jsonl also has keys that vary per world or are lists
/// (parked_displacement_m.<name>, plan_cost_history, plan_phase_times_s).
const std::vector<std::string>& resultColumns();

/// Columns and keys measured in wall-clock time: they differ between runs of the same episode.
/// Everything else is a function of the episode's parameters and the binary.
bool isTimingKey(std::string_view key);

/// `row` with its timing keys removed (for comparing runs).
nlohmann::ordered_json withoutTiming(const nlohmann::ordered_json& row);

/// The header line of results.csv, with its newline.
std::string csvHeader();
/// One CSV line for `row` (RFC 4180 quoting; booleans true/false; lists joined by '|').
std::string csvRow(const nlohmann::ordered_json& row);

/// Largest results.jsonl or results.csv read (docs/limits.md): a row is ~2 KB, so ~250,000
/// episodes; a parsed row takes a few times its text in memory.
inline constexpr std::uintmax_t kMaxResultsTableBytes = 512u << 20;

/// Every whole row of a results.jsonl; a torn or unparsable last line is skipped. Throws Error
/// naming the file and line for a bad line before the last, or when the file cannot be read.
/// A missing file has no rows.
std::vector<nlohmann::ordered_json> readResultsJsonl(const std::string& path);

/// Writes DIR/results.jsonl and DIR/results.csv with exactly `rows`, each file atomically.
void writeResultsTable(const std::string& dir, const std::vector<nlohmann::ordered_json>& rows);

class ResultsTable {
 public:
  /// Opens (creating, or repairing as described above) DIR/results.jsonl and DIR/results.csv.
  /// Throws Error when they cannot be opened or results.csv has another header (another
  /// parksim version's columns).
  explicit ResultsTable(const std::string& dir, double sync_interval_s = 1.0);
  ~ResultsTable();
  ResultsTable(const ResultsTable&) = delete;
  ResultsTable& operator=(const ResultsTable&) = delete;

  /// Ids already in the table, with whether each met its tolerance (met_tolerance).
  const std::map<std::string, bool>& done() const { return done_; }

  /// Appends one row (it must have episode_id and met_tolerance). Throws Error on a failed write.
  void append(const nlohmann::ordered_json& row);

  /// fdatasync both files now.
  void sync();

 private:
  std::string jsonl_path_;
  std::string csv_path_;
  int jsonl_fd_ = -1;
  int csv_fd_ = -1;
  double sync_interval_s_;
  double last_sync_s_ = 0.0;
  std::map<std::string, bool> done_;
};

}  // namespace parksim
