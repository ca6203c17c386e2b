#include "parksim/core/io/Csv.h"

#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>

#include "parksim/core/io/Error.h"
#include "parksim/core/io/InputFile.h"
#include "parksim/core/io/NumberFormat.h"

namespace parksim {

namespace {

// Splits the records of `text`; each record's first line is kept for messages.
std::vector<CsvTable::Row> parseRecords(std::string_view text, const std::string& source) {
  std::vector<CsvTable::Row> rows;
  CsvTable::Row row;
  std::string field;
  bool quoted = false;
  bool field_started = false;  // a field (possibly empty) exists on this record
  int line = 1;
  row.line = 1;
  auto endRecord = [&] {
    // A blank line is no record; a line with only commas is one of empty fields.
    if (field_started || !row.cells.empty()) {
      row.cells.push_back(std::move(field));
      rows.push_back(std::move(row));
    }
    row = {};
    field.clear();
    field_started = false;
  };
  int quote_line = 0;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    if (quoted) {
      if (c == '"') {
        if (i + 1 < text.size() && text[i + 1] == '"') {
          field += '"';
          ++i;
        } else {
          quoted = false;
        }
      } else {
        if (c == '\n') ++line;
        field += c;
      }
      continue;
    }
    switch (c) {
      case '"':
        quoted = true;
        quote_line = line;
        field_started = true;
        break;
      case ',':
        row.cells.push_back(std::move(field));
        field.clear();
        field_started = true;
        break;
      case '\r':
        if (i + 1 < text.size() && text[i + 1] == '\n') break;  // CRLF: the '\n' ends it
        field += c;
        field_started = true;
        break;
      case '\n':
        endRecord();
        ++line;
        row.line = line;
        break;
      default: field += c; field_started = true;
    }
  }
  if (quoted) {
    throw Error(source + ":" + std::to_string(quote_line) + ": quoted field is not closed");
  }
  endRecord();
  return rows;
}

}  // namespace

CsvTable::CsvTable(std::string_view text, std::string source) : source_(std::move(source)) {
  // A byte-order mark (spreadsheets' "CSV UTF-8") is no part of the first column's name.
  if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);
  std::vector<Row> records = parseRecords(text, source_);
  if (records.empty()) throw Error(source_ + ":1: empty file (expected a header line)");
  header_ = std::move(records.front().cells);
  records.erase(records.begin());
  rows_ = std::move(records);
}

std::optional<std::size_t> CsvTable::findColumn(std::span<const std::string_view> names) const {
  for (const std::string_view name : names) {
    for (std::size_t i = 0; i < header_.size(); ++i) {
      if (header_[i] == name) return i;
    }
  }
  return std::nullopt;
}

std::size_t CsvTable::column(std::string_view name) const {
  if (const std::optional<std::size_t> i = findColumn({name})) return *i;
  throw Error(source_ + ":1: header lacks column '" + std::string(name) + "'");
}

void CsvTable::fail(const Row& row, std::size_t column, const std::string& what) const {
  const std::string name = column < header_.size() ? header_[column] : std::to_string(column);
  throw Error(source_ + ":" + std::to_string(row.line) + ": column '" + name + "': " + what);
}

const std::string& CsvTable::cell(const Row& row, std::size_t column) const {
  if (column >= row.cells.size()) fail(row, column, "missing value");
  return row.cells[column];
}

double CsvTable::number(const Row& row, std::size_t column) const {
  const std::string& text = cell(row, column);
  // Spreadsheets and hand edits pad cells ("1, 2"); the padding is not part of the number.
  std::string_view digits = text;
  const std::size_t first = digits.find_first_not_of(" \t");
  digits = first == std::string_view::npos ? std::string_view() : digits.substr(first);
  digits = digits.substr(0, digits.find_last_not_of(" \t") + 1);
  double value = 0.0;
  if (!parseDouble(digits, value) || !std::isfinite(value)) {
    fail(row, column, "'" + text + "' is not a finite number");
  }
  return value;
}

CsvTable readCsvFile(const std::string& path, std::uintmax_t max_bytes) {
  return CsvTable(readInputFile(path, max_bytes, "CSV file"), path);
}

std::string csvField(std::string_view text) {
  if (text.find_first_of(",\"\r\n") == std::string_view::npos) return std::string(text);
  std::string quoted = "\"";
  for (const char c : text) {
    if (c == '"') quoted += '"';
    quoted += c;
  }
  quoted += '"';
  return quoted;
}

}  // namespace parksim
