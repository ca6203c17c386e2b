#include "parksim/pages/TableColumns.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <unordered_map>

#include "parksim/pages/ColumnCodec.h"

namespace parksim {
namespace {

using Json = nlohmann::ordered_json;

// A column with at most this many distinct numbers is stored as levels: exact values, and an
// axis's values read as they were written.
constexpr std::size_t kMaxNumberLevels = 256;
// Integers beyond 2^53 are not exact in a page's numbers: such a column is text.
constexpr double kExactIntegerLimit = 9007199254740992.0;

// Every key of the rows as a column: name -> one value per row (null where a row lacks it).
struct Columns {
  std::vector<std::string> names;
  std::unordered_map<std::string, std::vector<Json>> values;
  std::vector<std::string> omitted;
};

bool isPlain(const Json& v) { return !v.is_object() && !v.is_array(); }

void put(Columns& c, const std::string& name, std::size_t row, std::size_t rows, Json value) {
  auto [it, added] = c.values.try_emplace(name);
  if (added) {
    c.names.push_back(name);
    it->second.assign(rows, Json());
  }
  it->second[row] = std::move(value);
}

Columns collect(const std::vector<Json>& rows) {
  Columns c;
  std::map<std::string, bool> omitted;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    for (const auto& [key, value] : rows[i].items()) {
      if (value.is_object()) {
        for (const auto& [sub, v] : value.items()) {
          if (isPlain(v)) put(c, key + "." + sub, i, rows.size(), v);
        }
      } else if (value.is_array()) {
        const bool flat = std::all_of(value.begin(), value.end(), isPlain);
        if (!flat) {
          if (omitted.emplace(key, true).second) c.omitted.push_back(key);
          continue;
        }
        std::string joined;
        for (const Json& v : value) {
          if (!joined.empty()) joined += '|';
          joined += v.is_string() ? v.get<std::string>() : v.dump();
        }
        put(c, key, i, rows.size(), joined);
      } else {
        put(c, key, i, rows.size(), value);
      }
    }
  }
  return c;
}

const char* kindOf(const std::vector<Json>& values) {
  bool numbers = true;
  bool booleans = true;
  for (const Json& v : values) {
    if (v.is_null()) continue;
    numbers = numbers && v.is_number();
    booleans = booleans && v.is_boolean();
  }
  if (booleans) return "bool";
  return numbers ? "number" : "text";
}

// Levels sorted as a page sorts them: numbers by value, then everything else by its text.
bool levelLess(const Json& a, const Json& b) {
  if (a.is_number() != b.is_number()) return a.is_number();
  if (a.is_number()) return a.get<double>() < b.get<double>();
  return a.dump() < b.dump();
}

nlohmann::json levelsColumn(const std::vector<Json>& values) {
  std::map<std::string, Json> distinct;  // by text: 1 and 1.0 stay apart, as in the file
  for (const Json& v : values) distinct.emplace(v.dump(), v);
  std::vector<Json> levels;
  for (auto& [text, v] : distinct) levels.push_back(v);
  std::stable_sort(levels.begin(), levels.end(), levelLess);
  std::unordered_map<std::string, std::uint32_t> code;
  for (std::size_t i = 0; i < levels.size(); ++i) {
    code.emplace(levels[i].dump(), static_cast<std::uint32_t>(i));
  }
  std::vector<std::uint32_t> codes;
  codes.reserve(values.size());
  for (const Json& v : values) codes.push_back(code.at(v.dump()));
  nlohmann::json column = codeColumn(codes, static_cast<std::uint32_t>(levels.size()));
  column["encoding"] = "levels";
  column["levels"] = levels;
  return column;
}

// A numeric column: levels when few, integers when whole, else float32. Integers too large to
// be exact in a page's numbers become text levels (kind "text").
nlohmann::json numberColumn(const std::vector<Json>& values) {
  std::vector<double> numbers;
  std::vector<bool> present;
  bool whole = true;
  for (const Json& v : values) {
    present.push_back(!v.is_null());
    const double x = v.is_null() ? std::nan("") : v.get<double>();
    numbers.push_back(x);
    if (!v.is_null()) whole = whole && std::isfinite(x) && std::floor(x) == x;
  }
  std::vector<double> sorted;
  for (const double x : numbers) {
    if (!std::isnan(x)) sorted.push_back(x);
  }
  std::sort(sorted.begin(), sorted.end());
  const auto distinct =
      static_cast<std::size_t>(std::unique(sorted.begin(), sorted.end()) - sorted.begin());
  const bool exact = sorted.empty() || (std::fabs(sorted.front()) < kExactIntegerLimit &&
                                        std::fabs(sorted[distinct - 1]) < kExactIntegerLimit);
  if (whole && !exact) {
    std::vector<Json> texts;
    for (const Json& v : values) texts.push_back(v.is_null() ? Json() : Json(v.dump()));
    nlohmann::json column = levelsColumn(texts);
    column["kind"] = "text";
    return column;
  }
  if (distinct <= kMaxNumberLevels) return levelsColumn(values);
  if (whole) {
    std::vector<std::int64_t> integers;
    for (const double x : numbers)
      integers.push_back(std::isnan(x) ? 0 : static_cast<std::int64_t>(x));
    if (fitsIntegerColumn(integers)) {
      nlohmann::json column = integerColumn(integers, present);
      column["encoding"] = "integer";
      return column;
    }
  }
  nlohmann::json column = float32Column(numbers);
  column["encoding"] = "number";
  return column;
}

}  // namespace

nlohmann::json tableColumns(const std::vector<Json>& rows) {
  const Columns c = collect(rows);
  nlohmann::json columns = nlohmann::json::array();
  for (const std::string& name : c.names) {
    const std::vector<Json>& values = c.values.at(name);
    const char* kind = kindOf(values);
    nlohmann::json column;
    const bool constant =
        std::all_of(values.begin(), values.end(), [&](const Json& v) { return v == values[0]; });
    if (constant) {
      column = {{"encoding", "const"}, {"value", values.empty() ? Json() : values[0]}};
    } else if (std::string(kind) == "number") {
      column = numberColumn(values);
    } else {
      column = levelsColumn(values);
    }
    column["name"] = name;
    if (!column.contains("kind")) column["kind"] = kind;
    columns.push_back(std::move(column));
  }
  return {{"rows", rows.size()}, {"columns", std::move(columns)}, {"omitted", c.omitted}};
}

}  // namespace parksim
