#include "parksim/sweep/ResultsJUnit.h"

#include <algorithm>
#include <map>
#include <tuple>

#include "parksim/core/NumberFormat.h"
#include "parksim/sweep/Report.h"

namespace parksim {

namespace {

using Row = nlohmann::ordered_json;

// appendParamColumns' keys (EpisodeParams.h), in its order.
constexpr const char* kParamKeys[] = {
    "world",          "world_file",     "planner",   "steering",  "smooth",       "seed",
    "max_iterations", "tracking",       "timing",    "realism",   "noise_seed",   "start_dx_m",
    "start_dy_m",     "start_dyaw_deg", "goal_dx_m", "goal_dy_m", "goal_dyaw_deg"};

std::string text(const Row& row, const char* key) {
  const auto it = row.find(key);
  if (it == row.end() || it->is_null()) return "";
  return it->is_string() ? it->get<std::string>() : it->dump();
}

double numberOr(const Row& row, const char* key, double fallback) {
  const auto it = row.find(key);
  return it != row.end() && it->is_number() ? it->get<double>() : fallback;
}

// Seeds are 64-bit: compared as integers, not as doubles.
std::uint64_t seedOf(const Row& row, const char* key) {
  const auto it = row.find(key);
  return it != row.end() && it->is_number_unsigned() ? it->get<std::uint64_t>() : 0;
}

// " start=dx,dy,dyaw" when the row's offset is not zero.
std::string offsetText(const Row& row, const char* what) {
  const std::string p = what;
  const std::string dx = text(row, (p + "_dx_m").c_str());
  const std::string dy = text(row, (p + "_dy_m").c_str());
  const std::string dyaw = text(row, (p + "_dyaw_deg").c_str());
  const auto zero = [](const std::string& v) { return v.empty() || v == "0" || v == "0.0"; };
  if (zero(dx) && zero(dy) && zero(dyaw)) return "";
  return " " + p + "=" + dx + "," + dy + "," + dyaw;
}

std::string caseName(const Row& row) {
  return "seed=" + text(row, "seed") + " noise_seed=" + text(row, "noise_seed") +
         offsetText(row, "start") + offsetText(row, "goal") + " id=" + text(row, "episode_id");
}

// The numbers a reader of a failure wants next to its line.
std::string failureText(const Row& row) {
  std::string s = text(row, "failure");
  const auto mm = [&](const char* key) {
    const auto it = row.find(key);
    return it != row.end() && it->is_number() ? formatFixed(it->get<double>() * 1e3, 3) + " mm"
                                              : std::string("-");
  };
  if (row.contains("max_pos_err_m")) {
    s += "\nmax tracking error " + mm("max_pos_err_m") + ", goal error " + mm("goal_pos_err_m") +
         " / " + text(row, "goal_heading_err_deg") + " deg, " + text(row, "contacts") +
         " contact events";
  }
  return s;
}

JUnitCase rowCase(const Row& row, const std::string& suite) {
  JUnitCase c;
  c.name = caseName(row);
  c.classname = suite;
  c.time_s = numberOr(row, "episode_wall_s", 0.0);
  c.properties.push_back({"episode_id", text(row, "episode_id")});
  for (const char* key : kParamKeys) {
    if (row.contains(key)) c.properties.push_back({key, text(row, key)});
  }
  const std::string status = text(row, "status");
  c.properties.push_back({"status", status});
  const auto met = row.find("met_tolerance");
  if (met == row.end() || !met->is_boolean() || !met->get<bool>()) {
    const std::string line = text(row, "failure");
    c.failure = JUnitFailure{line.empty() ? "did not meet its tolerance (" + status + ")" : line,
                             status.empty() ? "failed" : status, failureText(row)};
  }
  return c;
}

}  // namespace

JUnitReport resultsJUnit(const std::vector<Row>& rows, const std::string& name) {
  std::map<RowGroupKey, std::vector<const Row*>> groups;
  for (const Row& row : rows) groups[rowGroupKey(row)].push_back(&row);
  JUnitReport report{name, {}};
  for (auto& [key, members] : groups) {
    const auto order = [](const Row* a, const Row* b) {
      const auto key_of = [](const Row* r) {
        return std::make_tuple(seedOf(*r, "seed"), seedOf(*r, "noise_seed"),
                               text(*r, "episode_id"));
      };
      return key_of(a) < key_of(b);
    };
    std::sort(members.begin(), members.end(), order);
    JUnitSuite suite;
    suite.name = rowGroupName(key);
    for (const Row* row : members) suite.cases.push_back(rowCase(*row, suite.name));
    report.suites.push_back(std::move(suite));
  }
  return report;
}

}  // namespace parksim
