#pragma once
// The files of a results table, DIR/results.jsonl (one sealed JSON object per line, every key;
// the reference) and DIR/results.csv (the columns of resultColumns(), the rendering of the
// same rows), read one line at a time and written whole. The appending writer of a running
// sweep is ResultsTable.h; the seal of a row is RowSeal.h.
//
// Readers keep one line in memory, not the table: `merge`, `report`, `verify` and a resumed
// sweep read 100,000-row tables in seconds (docs/sweeps.md, "Scale").

#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

namespace parksim {

/// results.csv's columns, in order: the episode record's (EpisodeRecord.h: episode_id, the
/// parameters, the outcome, plan statistics, simulation metrics, the realism layers, timing,
/// provenance and row_checksum, last), with a table's set columns (`set:` paths, sorted) after
/// the parameters. Keys a row lacks (a failed plan has no simulation) are empty cells.
/// results.jsonl also has keys that vary per world or are lists (parked_displacement_m.<name>,
/// plan_cost_history, plan_phase_times_s).
std::vector<std::string> resultColumns(const std::vector<std::string>& set_columns = {});

/// The set columns of a table whose results.csv header line (without its newline) is `header`,
/// or nullopt when it is not one resultColumns gives (another parksim's columns).
std::optional<std::vector<std::string>> setColumnsOfHeader(std::string_view header);

/// The set keys of `row` (EpisodeRecord.h's isSetKey) added to `keys`.
void addSetKeys(const nlohmann::ordered_json& row, std::set<std::string, std::less<>>& keys);

/// Columns and keys measured in wall-clock time: they differ between runs of the same episode.
/// Everything else is a function of the episode's parameters and the binary.
bool isTimingKey(std::string_view key);

/// `row` without its timing keys and its seal (for comparing runs).
nlohmann::ordered_json withoutTiming(const nlohmann::ordered_json& row);

/// The header line of results.csv with `columns` (resultColumns), with its newline.
std::string csvHeader(const std::vector<std::string>& columns);
/// One CSV line for `row` (RFC 4180 quoting; booleans true/false; lists joined by '|') in
/// `columns`. `checksum`, when given, fills the row_checksum column of a row that lacks the key.
std::string csvRow(const nlohmann::ordered_json& row, const std::vector<std::string>& columns,
                   std::string_view checksum = {});

/// Largest results.jsonl or results.csv read (docs/limits.md): a row is ~2.5 KB, so ~200,000
/// episodes. Readers hold one line at a time, so this bounds time, not memory.
inline constexpr std::uintmax_t kMaxResultsTableBytes = 512u << 20;

/// One whole row of a results.jsonl, as a visitor sees it.
struct TableRow {
  const nlohmann::ordered_json& row;  ///< parsed; row_checksum is its last key
  std::string_view text;              ///< the line as written, without its newline
  std::size_t line = 0;               ///< 1-based
  std::uint64_t offset = 0;           ///< of the line's first byte in the file
};

using TableRowVisitor = std::function<void(const TableRow&)>;

/// Receives a row that fails the checks (its 1-based line and what is wrong) when a scan is to
/// go on past it (`parksim verify`).
using TableProblemVisitor = std::function<void(std::size_t line, const std::string& what)>;

/// What a scan of results.jsonl found besides its rows.
struct TableScan {
  std::size_t rows = 0;
  /// Bytes of the whole rows: the file's length, less a torn last line.
  std::uint64_t whole_bytes = 0;
  /// The file ended in a line without its newline (a writer killed mid-row), which was skipped.
  bool torn_tail = false;
};

/// Reads the results.jsonl at `path` one line at a time, checks each row (JSON object with a
/// string episode_id, keys parksim reads of the right type, an intact seal: RowSeal.h) and
/// calls `visit` for it, in file order. Throws Error "<path>:<line>: <what>" at the first row
/// that fails, or when the file cannot be read (a regular file within kMaxResultsTableBytes).
/// A missing file has no rows. With `on_problem`, a row that fails is passed to it instead and
/// the scan goes on.
TableScan scanResultsJsonl(const std::string& path, const TableRowVisitor& visit,
                           const TableProblemVisitor& on_problem = {});

/// Every whole row of a results.jsonl (scanResultsJsonl's checks), in file order. For small
/// tables: a parsed row takes ~8 KB of memory.
std::vector<nlohmann::ordered_json> readResultsJsonl(const std::string& path);

/// The world contents and builds the rows of one or more tables come from (RowSeal.h's
/// world_hash and rowWriter), so that a mix is flagged instead of being read as one experiment.
class TableOrigins {
 public:
  /// Notes `row`, found at `path`:`line`.
  void add(const nlohmann::ordered_json& row, const std::string& path, std::size_t line);
  /// One line per mix, naming where each variant was first seen, e.g. "<file>:40: world
  /// 'head_in' has another content (world_hash 4567...) than at <file>:1 (0123...): the world
  /// file changed between runs"; empty when every world has one content and every row one build.
  std::vector<std::string> mixes() const;

 private:
  /// world name -> world_hash -> where first seen ("file:line")
  std::map<std::string, std::map<std::string, std::string>> world_hashes_;
  /// rowWriter -> where first seen
  std::map<std::string, std::string> writers_;
  std::size_t order_ = 0;  // insertion counter: variants are listed in the order they were seen
  std::map<std::string, std::size_t> seen_at_;
};

/// A results table read whole and checked, for commands that need every row at once (report,
/// compare): ~8 KB of memory per row.
struct VerifiedTable {
  std::string path;                          ///< the results.jsonl read
  std::vector<nlohmann::ordered_json> rows;  ///< every whole row, in file order
  /// Where the rows come from; origins.mixes() lists rows of other world contents or builds,
  /// which a reader should refuse or flag.
  TableOrigins origins;
  bool torn_tail = false;  ///< a torn last line (a killed sweep) was skipped
};

/// Reads DIR/results.jsonl, or the file itself when `path` names a file, with
/// scanResultsJsonl's checks: throws Error "<file>:<line>: ..." at the first changed or
/// malformed row, and when there is no such table.
VerifiedTable readVerifiedTable(const std::string& path);

/// Follows results.csv line by line against the rendering (csvRow) of the rows of
/// results.jsonl, keeping one row in memory: what `verify` and a resumed sweep use to find a
/// changed line of results.csv.
class CsvFollower {
 public:
  /// Opens `path` (a missing file reads as empty). Throws Error when it cannot be read.
  explicit CsvFollower(const std::string& path);
  ~CsvFollower();
  CsvFollower(const CsvFollower&) = delete;
  CsvFollower& operator=(const CsvFollower&) = delete;

  enum class Match { kSame, kEnded, kDiffers };
  /// Compares the next bytes of the file with `expected` (a header or a row): kSame and
  /// advances; kEnded when the file ends before all of `expected` (a writer stopped there);
  /// kDiffers otherwise (line() is then the file's line that differs).
  Match next(std::string_view expected);
  /// 1-based line of the file where the next comparison starts (or the one that differed).
  std::size_t line() const { return line_; }
  /// True when the file has bytes beyond everything compared.
  bool hasMore();
  /// Skips the rest of the current line (after a row that differed or could not be rendered).
  void skipLine();
  /// Reads the next whole line (without its newline) into `line` and advances past it; false,
  /// reading nothing, when the file ends before a newline.
  bool nextLine(std::string& line);

 private:
  bool fill();
  int fd_ = -1;
  std::string buffer_;
  std::size_t pos_ = 0;
  std::size_t line_ = 1;
  std::uint64_t total_ = 0;  ///< bytes read so far: the file's size limit holds over all reads
  bool eof_ = false;
  std::string path_;
};

/// Writes DIR/results.jsonl and DIR/results.csv whole: both are written to temporary files
/// first and renamed over the tables only when both are complete, so a full disk or a kill
/// leaves the earlier pair (or none) in place. Rows are added one at a time as their
/// results.jsonl lines (sealed) with their parsed rows.
class ResultsTableWriter {
 public:
  /// results.csv gets resultColumns(set_columns).
  explicit ResultsTableWriter(const std::string& dir,
                              const std::vector<std::string>& set_columns = {});
  ~ResultsTableWriter();  ///< removes the temporary files unless committed
  ResultsTableWriter(const ResultsTableWriter&) = delete;
  ResultsTableWriter& operator=(const ResultsTableWriter&) = delete;

  /// Appends a sealed row: its line as written (without newline) and the row it parses to.
  void add(std::string_view sealed_line, const nlohmann::ordered_json& row);
  /// Flushes, syncs and renames both files into place. Throws Error (e.g. a full disk).
  void commit();

 private:
  struct TempFile;
  std::string dir_;
  std::vector<std::string> columns_;
  std::unique_ptr<TempFile> jsonl_;
  std::unique_ptr<TempFile> csv_;
  bool committed_ = false;
};

/// Writes DIR/results.csv anew from DIR/results.jsonl (checked as scanResultsJsonl does),
/// through a temporary file renamed into place. Its set columns are those of the rows and
/// `set_columns` (a sweep's set: paths that no row has yet); returns them.
std::vector<std::string> rebuildResultsCsv(const std::string& dir,
                                           const std::vector<std::string>& set_columns = {});

/// Writes DIR/results.jsonl and DIR/results.csv with exactly `rows` (ResultsTableWriter; the
/// set columns of the rows), sealing rows that are not sealed yet.
void writeResultsTable(const std::string& dir, const std::vector<nlohmann::ordered_json>& rows);

}  // namespace parksim
