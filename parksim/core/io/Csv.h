#pragma once
// The one CSV reader (and the field quoting of the writers) for parksim's tables: trajectory.csv,
// executed.csv, bench.csv. Comma-separated, a header line naming the columns, fields quoted
// with '"' when they hold a comma, quote or line break ("" inside quotes is one quote), CRLF or
// LF line ends, blank lines ignored. Numbers are parsed with std::from_chars, so reading does
// not depend on the locale (parksim/core/io/NumberFormat.h). Errors are parksim::Error with
// "<file>:<line>: column '<name>': <what>".

#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace parksim {

class CsvTable {
 public:
  struct Row {
    int line = 0;  ///< 1-based line of the file the row starts on
    std::vector<std::string> cells;
  };

  /// Parses `text`; `source` names it in messages (usually the file path). Throws Error when
  /// there is no header line or a quoted field is not closed.
  CsvTable(std::string_view text, std::string source);

  const std::string& source() const { return source_; }
  const std::vector<std::string>& header() const { return header_; }
  const std::vector<Row>& rows() const { return rows_; }

  /// The index of the first of `names` that is a column, or nothing.
  std::optional<std::size_t> findColumn(std::span<const std::string_view> names) const;
  std::optional<std::size_t> findColumn(std::initializer_list<std::string_view> names) const {
    return findColumn(std::span<const std::string_view>(names.begin(), names.size()));
  }
  /// The index of column `name`. Throws Error ("<file>:1: header lacks column 'x'").
  std::size_t column(std::string_view name) const;

  /// The cell of `row` in `column`. Throws Error when the row is too short.
  const std::string& cell(const Row& row, std::size_t column) const;
  /// The cell as a finite number (surrounding blanks ignored). Throws Error naming file, line,
  /// column and the text.
  double number(const Row& row, std::size_t column) const;

 private:
  [[noreturn]] void fail(const Row& row, std::size_t column, const std::string& what) const;

  std::string source_;
  std::vector<std::string> header_;
  std::vector<Row> rows_;
};

/// Largest file readCsvFile reads by default (docs/limits.md). A table holds every cell as a
/// string, up to ~32 bytes of memory per byte of input (a file of commas), so 32 MiB bounds
/// a table to about 1 GB; an executed.csv of ~100,000 rows fits.
inline constexpr std::uintmax_t kMaxCsvFileBytes = 32u << 20;

/// Reads and parses the regular file at `path`, at most `max_bytes` long. Throws Error
/// ("<file>: cannot open ...", "... is not a regular file ...", "... more than the limit ...").
CsvTable readCsvFile(const std::string& path, std::uintmax_t max_bytes = kMaxCsvFileBytes);

/// `text` as one CSV field: unchanged, or quoted when it holds a comma, quote or line break.
std::string csvField(std::string_view text);

}  // namespace parksim
