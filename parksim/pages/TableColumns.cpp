#include "parksim/pages/TableColumns.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <deque>
#include <limits>
#include <set>
#include <string_view>
#include <unordered_map>
#include <unordered_set>

#include "parksim/pages/ColumnCodec.h"

namespace parksim {
namespace {

using Json = nlohmann::ordered_json;

// A column with at most this many distinct numbers is stored as levels: exact values, and an
// axis's values read as they were written.
constexpr std::size_t kMaxNumberLevels = 256;
// Integers beyond 2^53 are not exact in a page's numbers: such a column is text.
constexpr double kExactIntegerLimit = 9007199254740992.0;

const Json kNull;

// A row without a code yet: a number, or no value.
constexpr std::uint32_t kNoCode = 0xFFFFFFFFu;

// A value's identity among a column's levels, cheaper than its JSON text.
std::string levelKey(const Json& v) {
  switch (v.type()) {
    case Json::value_t::string: return "s" + v.get_ref<const std::string&>();
    case Json::value_t::boolean: return v.get<bool>() ? "t" : "f";
    case Json::value_t::null: return "z";
    default: return "j" + v.dump();
  }
}

// One key of the rows, with what its values are learnt while the rows are read, one row after
// another (the rows are far apart in memory: a second pass per column would wait on memory for
// most of its time).
struct Column {
  std::string name;
  /// Each row's value; null where a row lacks it.
  std::vector<const Json*> values;
  /// The values as numbers (NaN where missing) while every value is a number.
  std::vector<double> numbers;
  bool all_numbers = true;
  bool all_booleans = true;
  bool constant = true;
  const Json* first = nullptr;  // the first row's value (null: the row lacks it)
  bool whole = true;            // every number an integer
  double lo = std::numeric_limits<double>::infinity();
  double hi = -std::numeric_limits<double>::infinity();
  /// Distinct numbers, counted only up to kMaxNumberLevels + 1: enough to choose.
  std::unordered_set<double> distinct;
  double last = std::nan("");  // the last number added
  /// Levels of the values that are not numbers, in the order first seen, and each row's code
  /// (kNoCode for a number or a missing value): a text column's levels need no second pass.
  /// Kept from the first row that differs from the first (rows before it backfilled): a
  /// constant column, most of a table's, costs no lookups.
  bool tracking = false;
  std::unordered_map<std::string_view, std::uint32_t> string_codes;
  std::unordered_map<std::string, std::uint32_t> other_codes;
  std::vector<const Json*> levels;
  std::vector<std::uint32_t> codes;

  const Json& at(std::size_t i) const { return values[i] != nullptr ? *values[i] : kNull; }

  void add(std::size_t row, const Json* value) {
    values[row] = value;
    const Json& v = value != nullptr ? *value : kNull;
    if (row == 0) {
      first = value;
    } else if (constant) {
      constant = v == (first != nullptr ? *first : kNull);
    }
    if (!constant && !tracking) {
      tracking = true;
      for (std::size_t r = 0; r < row; ++r) track(r);
    }
    if (tracking) track(row);
    if (v.is_null()) return;
    all_booleans = all_booleans && v.is_boolean();
    if (!all_numbers) return;
    if (!v.is_number()) {
      all_numbers = false;
      numbers = {};
      return;
    }
    const double x = v.get<double>();
    numbers[row] = x;
    whole = whole && std::isfinite(x) && std::floor(x) == x;
    lo = std::min(lo, x);
    hi = std::max(hi, x);
    // Rows often repeat the row before's value (a sweep's axes change slowly): no lookup then.
    if (distinct.size() <= kMaxNumberLevels && !(x == last)) distinct.insert(x);
    last = x;
  }

  /// Gives row `row` its value's level code (none for a number or no value).
  void track(std::size_t row) {
    const Json* value = values[row];
    if (value == nullptr || value->is_null() || value->is_number()) return;
    const auto next = static_cast<std::uint32_t>(levels.size());
    std::uint32_t code = next;
    if (value->is_string()) {
      code = string_codes.try_emplace(value->get_ref<const std::string&>(), next).first->second;
    } else {
      code = other_codes.try_emplace(levelKey(*value), next).first->second;
    }
    if (code == next) levels.push_back(value);
    codes[row] = code;
  }

  /// A row that lacks the key, found after the column was made.
  void missing(std::size_t row) {
    if (row > 0 && first != nullptr) constant = false;
  }
};

struct Columns {
  std::vector<Column> columns;
  std::deque<Json> made;  // joined lists, which no row holds as such
  std::vector<std::string> omitted;
};

bool isPlain(const Json& v) { return !v.is_object() && !v.is_array(); }

// Finds columns by name, quickly for rows that list their keys in the order of the row before
// (all of a sweep's rows do): the column of the n-th name of a row is remembered.
class ColumnFinder {
 public:
  ColumnFinder(Columns& c, std::size_t rows) : c_(c), rows_(rows) {}

  void startRow() { at_ = 0; }

  Column& column(const std::string& key, const std::string& sub = {}) {
    if (at_ < seen_.size() && seen_[at_].key == key && seen_[at_].sub == sub) {
      return c_.columns[seen_[at_++].column];
    }
    const std::string name = sub.empty() ? key : key + "." + sub;
    auto [it, added] = index_.try_emplace(name, c_.columns.size());
    if (added) {
      Column& made = c_.columns.emplace_back();
      made.name = name;
      made.values.assign(rows_, nullptr);
      made.numbers.assign(rows_, std::nan(""));
      made.codes.assign(rows_, kNoCode);
    }
    if (at_ >= seen_.size()) seen_.resize(at_ + 1);
    seen_[at_++] = {key, sub, it->second};
    return c_.columns[it->second];
  }

 private:
  struct Seen {
    std::string key;
    std::string sub;
    std::size_t column = 0;
  };
  Columns& c_;
  std::size_t rows_;
  std::unordered_map<std::string, std::size_t> index_;
  std::vector<Seen> seen_;
  std::size_t at_ = 0;
};

Columns collect(const std::vector<Json>& rows) {
  Columns c;
  ColumnFinder find(c, rows.size());
  std::set<std::string> omitted;
  std::vector<std::size_t> filled;  // per column: rows given a value
  for (std::size_t i = 0; i < rows.size(); ++i) {
    find.startRow();
    for (const auto& [key, value] : rows[i].items()) {
      if (value.is_object()) {
        for (const auto& [sub, v] : value.items()) {
          if (isPlain(v)) find.column(key, sub).add(i, &v);
        }
      } else if (value.is_array()) {
        if (!std::all_of(value.begin(), value.end(), isPlain)) {
          if (omitted.insert(key).second) c.omitted.push_back(key);
          continue;
        }
        std::string joined;
        for (const Json& v : value) {
          if (!joined.empty()) joined += '|';
          joined += v.is_string() ? v.get<std::string>() : v.dump();
        }
        find.column(key).add(i, &c.made.emplace_back(std::move(joined)));
      } else {
        find.column(key).add(i, &value);
      }
    }
  }
  // Rows without a column's key: no value, and the column is not constant unless none has it.
  for (Column& column : c.columns) {
    for (std::size_t i = 0; i < rows.size() && column.constant; ++i) {
      if (column.values[i] == nullptr) column.missing(i);
    }
  }
  return c;
}

// Levels in the order a page sorts them: numbers by value, strings by their bytes, then
// anything else by its JSON text; `codes` renumbered to match.
Json sortLevels(std::vector<Json> levels, std::vector<std::uint32_t>& codes) {
  const auto rank = [](const Json& x) { return x.is_number() ? 0 : x.is_string() ? 1 : 2; };
  std::vector<std::uint32_t> order(levels.size());
  for (std::uint32_t k = 0; k < order.size(); ++k) order[k] = k;
  std::stable_sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
    const Json& x = levels[a];
    const Json& y = levels[b];
    if (rank(x) != rank(y)) return rank(x) < rank(y);
    if (x.is_number()) return x.get<double>() < y.get<double>();
    if (x.is_string()) return x.get_ref<const std::string&>() < y.get_ref<const std::string&>();
    return x.dump() < y.dump();
  });
  std::vector<std::uint32_t> position(levels.size());
  Json sorted = Json::array();
  for (std::uint32_t k = 0; k < order.size(); ++k) {
    position[order[k]] = k;
    sorted.push_back(std::move(levels[order[k]]));
  }
  for (std::uint32_t& code : codes) code = position[code];
  return sorted;
}

// Beyond this many levels (ids, failure lines) they stay in the order first seen: a page sorts
// rows itself, and offers a list to filter by only for a few levels.
constexpr std::size_t kMaxSortedLevels = 256;

nlohmann::json levelsOf(std::vector<Json> levels, std::vector<std::uint32_t> codes) {
  Json sorted = levels.size() <= kMaxSortedLevels ? sortLevels(std::move(levels), codes)
                                                  : Json(std::move(levels));
  nlohmann::json column = codeColumn(codes, static_cast<std::uint32_t>(sorted.size()));
  column["encoding"] = "levels";
  column["levels"] = std::move(sorted);
  return column;
}

// The values as distinct values and a code per row. `as_text`: numbers as their JSON text
// (integers too large for a page's numbers).
nlohmann::json levelsColumn(const Column& c, bool as_text = false) {
  std::vector<Json> levels;
  std::vector<std::uint32_t> codes;
  if (!as_text && c.numbers.empty() && c.tracking) {
    // No number among the values: the levels collected with the rows, and no value as null.
    for (const Json* level : c.levels) levels.push_back(*level);
    codes = c.codes;
    const auto none = static_cast<std::uint32_t>(levels.size());
    bool any_missing = false;
    for (std::uint32_t& code : codes) {
      if (code == kNoCode) {
        code = none;
        any_missing = true;
      }
    }
    if (any_missing) levels.emplace_back();
  } else {
    // Numbers among them (as text, or mixed with text), or a column that differed only by a
    // row lacking its key: another pass over the rows.
    std::unordered_map<std::string, std::uint32_t> index;
    codes.reserve(c.values.size());
    for (std::size_t i = 0; i < c.values.size(); ++i) {
      const Json& v = c.at(i);
      const auto [it, added] =
          index.try_emplace(levelKey(v), static_cast<std::uint32_t>(levels.size()));
      if (added) levels.push_back(as_text && v.is_number() ? Json(v.dump()) : v);
      codes.push_back(it->second);
    }
  }
  nlohmann::json column = levelsOf(std::move(levels), std::move(codes));
  if (as_text) column["kind"] = "text";
  return column;
}

// Few distinct numbers: levels, by value; each level as its first row wrote it.
nlohmann::json numberLevelsColumn(const Column& c) {
  std::unordered_map<double, std::uint32_t> index;
  std::vector<Json> levels;
  std::vector<std::uint32_t> codes;
  codes.reserve(c.numbers.size());
  std::uint32_t none = 0;
  bool any_missing = false;
  for (std::size_t i = 0; i < c.numbers.size(); ++i) {
    const double x = c.numbers[i];
    if (std::isnan(x)) {
      if (!any_missing) {
        any_missing = true;
        none = static_cast<std::uint32_t>(levels.size());
        levels.emplace_back();
      }
      codes.push_back(none);
      continue;
    }
    const auto [it, added] = index.try_emplace(x, static_cast<std::uint32_t>(levels.size()));
    if (added) levels.push_back(c.at(i));
    codes.push_back(it->second);
  }
  return levelsOf(std::move(levels), std::move(codes));
}

// A numeric column: levels when few, integers when whole, else float32. Integers too large to
// be exact in a page's numbers become text levels (kind "text").
nlohmann::json numberColumn(const Column& c) {
  const bool exact = std::fabs(c.lo) < kExactIntegerLimit && std::fabs(c.hi) < kExactIntegerLimit;
  if (c.whole && !exact) return levelsColumn(c, true);
  if (c.distinct.size() <= kMaxNumberLevels) return numberLevelsColumn(c);
  if (c.whole) {
    std::vector<std::int64_t> integers;
    std::vector<bool> present;
    integers.reserve(c.numbers.size());
    present.reserve(c.numbers.size());
    for (const double x : c.numbers) {
      integers.push_back(std::isnan(x) ? 0 : static_cast<std::int64_t>(x));
      present.push_back(!std::isnan(x));
    }
    if (fitsIntegerColumn(integers)) {
      nlohmann::json column = integerColumn(integers, present);
      column["encoding"] = "integer";
      return column;
    }
  }
  nlohmann::json column = float32Column(c.numbers);
  column["encoding"] = "number";
  return column;
}

}  // namespace

nlohmann::json tableColumns(const std::vector<Json>& rows) {
  const Columns c = collect(rows);
  nlohmann::json columns = nlohmann::json::array();
  for (const Column& column : c.columns) {
    const char* kind = column.all_booleans ? "bool" : column.all_numbers ? "number" : "text";
    nlohmann::json packed;
    if (column.constant) {
      packed = {{"encoding", "const"}, {"value", column.at(0)}};
    } else if (std::string_view(kind) == "number") {
      packed = numberColumn(column);
    } else {
      packed = levelsColumn(column);
    }
    packed["name"] = column.name;
    if (!packed.contains("kind")) packed["kind"] = kind;
    columns.push_back(std::move(packed));
  }
  return {{"rows", rows.size()}, {"columns", std::move(columns)}, {"omitted", c.omitted}};
}

}  // namespace parksim
