#include "parksim/compare/RowPairing.h"

#include <algorithm>
#include <utility>

#include "parksim/core/io/Error.h"
#include "parksim/results/tables/EpisodeRecord.h"

namespace parksim {
namespace {

using Json = nlohmann::ordered_json;

constexpr std::string_view kAllowed = "planner, controller, planner.NAME, controller.NAME";

bool startsWith(std::string_view s, std::string_view prefix) {
  return s.size() > prefix.size() && s.substr(0, prefix.size()) == prefix;
}

// A parameter column: a parameter field of the record or a set: column. world_file is
// provenance (the file the world came from), left out of ids and so of pairing.
bool isParameterColumn(std::string_view key) {
  if (key == "world_file") return false;
  if (isSetKey(key)) return true;
  const EpisodeField* f = findField(key);
  return f != nullptr && f->group == FieldGroup::kParameter;
}

}  // namespace

std::string acrossColumnProblem(std::string_view column) {
  if (column == "planner" || column == "controller" || startsWith(column, "planner.") ||
      startsWith(column, "controller.")) {
    return "";
  }
  return "'" + std::string(column) +
         "' is not a column to compare across (allowed: " + std::string(kAllowed) + ")";
}

RowPairing::RowPairing(std::vector<std::string> across) {
  for (std::string& column : across) {
    const std::string problem = acrossColumnProblem(column);
    if (!problem.empty()) throw Error("across: " + problem);
    if (!isAcross(column)) across_.push_back(std::move(column));
  }
}

bool RowPairing::isAcross(std::string_view column) const {
  if (std::find(across_.begin(), across_.end(), column) != across_.end()) return true;
  // Across a planner (controller), its own parameters differ with it.
  for (const char* component : {"planner", "controller"}) {
    if (startsWith(column, std::string(component) + ".") &&
        std::find(across_.begin(), across_.end(), component) != across_.end()) {
      return true;
    }
  }
  return false;
}

RowGroupKey RowPairing::groupKey(const Json& row) const {
  if (across_.empty()) return rowGroupKey(row);
  // The group of the row without the columns compared across: its label names neither them
  // nor (for the planner) the planner, which reads "*".
  Json rest = row;
  for (auto it = rest.begin(); it != rest.end();) {
    it = isAcross(it.key()) && it.key() != "planner" ? rest.erase(it) : std::next(it);
  }
  if (isAcross("planner")) rest["planner"] = "*";
  return rowGroupKey(rest);
}

std::string RowPairing::pairKey(const Json& row) const {
  if (across_.empty()) {
    const auto it = row.find("episode_id");
    return it != row.end() && it->is_string() ? it->get<std::string>() : std::string();
  }
  std::vector<std::pair<std::string, std::string>> parts;
  for (const auto& [key, value] : row.items()) {
    if (isParameterColumn(key) && !isAcross(key)) parts.emplace_back(key, value.dump());
  }
  std::sort(parts.begin(), parts.end());
  std::string s;
  for (const auto& [key, value] : parts) {
    s += key;
    s += '=';
    s += value;
    s += ';';
  }
  return s;
}

std::string RowPairing::valueText(const Json& row, const std::string& column) {
  const auto it = row.find(column);
  if (it == row.end() || it->is_null()) return "(none)";
  return it->is_string() ? it->get<std::string>() : it->dump();
}

}  // namespace parksim
