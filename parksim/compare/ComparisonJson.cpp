#include "parksim/compare/ComparisonJson.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <tuple>

#include "parksim/compare/RowPairing.h"

namespace parksim {
namespace {

using Json = nlohmann::ordered_json;

nlohmann::json number(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(); }

nlohmann::json side(const Json& row) {
  nlohmann::json s = {{"status", row.value("status", "")},
                      {"met", row.value("met_tolerance", false)}};
  for (const char* key : {"max_pos_err_m", "goal_pos_err_m"}) {
    const auto it = row.find(key);
    s[key] = it != row.end() && it->is_number() ? number(it->get<double>()) : nlohmann::json();
  }
  return s;
}

// Episodes of both tables by group name: (baseline id, baseline row, candidate row).
using Pair = std::tuple<std::string, const Json*, const Json*>;

// Paired as compareTables pairs them: by group and RowPairing::pairKey (the id by default).
std::map<std::string, std::vector<Pair>> pairsByGroup(const std::vector<Json>& baseline,
                                                      const std::vector<Json>& candidate,
                                                      const RowPairing& pairing) {
  std::map<std::pair<std::string, std::string>, const Json*> by_key;
  const auto keyOf = [&](const Json& row) {
    return std::make_pair(rowGroupName(pairing.groupKey(row)), pairing.pairKey(row));
  };
  for (const Json& row : candidate) by_key.emplace(keyOf(row), &row);
  std::map<std::string, std::vector<Pair>> groups;
  for (const Json& row : baseline) {
    const std::string id = row.value("episode_id", "");
    const auto key = keyOf(row);
    const auto it = by_key.find(key);
    if (id.empty() || it == by_key.end()) continue;
    groups[key.first].emplace_back(id, &row, it->second);
  }
  return groups;
}

// Worst first: newly failed, failed in both, then the largest growth of the max error.
void orderPairs(std::vector<Pair>& pairs) {
  const auto rank = [](const Pair& p) {
    const bool before = std::get<1>(p)->value("met_tolerance", false);
    const bool after = std::get<2>(p)->value("met_tolerance", false);
    const int failure = before && !after ? 0 : (!before && !after ? 1 : 2);
    const auto err = [](const Json* row) {
      const auto it = row->find("max_pos_err_m");
      return it != row->end() && it->is_number() ? it->get<double>() : 0.0;
    };
    return std::make_tuple(failure, -(err(std::get<2>(p)) - err(std::get<1>(p))), std::get<0>(p));
  };
  std::sort(pairs.begin(), pairs.end(),
            [&](const Pair& a, const Pair& b) { return rank(a) < rank(b); });
}

nlohmann::json metricJson(const MetricComparison& m, const CompareDef& def) {
  return {{"name", m.name},
          {"key", m.key},
          {"q", m.q},
          {"tested", m.tested},
          {"note", m.note},
          {"baseline_n", m.baseline_n},
          {"candidate_n", m.candidate_n},
          {"baseline_met", m.baseline_met},
          {"candidate_met", m.candidate_met},
          {"baseline", number(m.baseline)},
          {"candidate", number(m.candidate)},
          {"ci_low", number(m.ci_low)},
          {"ci_high", number(m.ci_high)},
          {"p", number(m.p)},
          {"p_adjusted", number(m.p_adjusted)},
          {"regression", m.regression},
          {"line", metricLine(m, def)}};
}

}  // namespace

nlohmann::json comparisonJson(const TableComparison& t, const CompareDef& def,
                              const ComparisonSources& sources, const std::vector<Json>& baseline,
                              const std::vector<Json>& candidate) {
  std::map<std::string, std::vector<Pair>> pairs =
      pairsByGroup(baseline, candidate, RowPairing(def.across));
  nlohmann::json groups = nlohmann::json::array();
  for (const GroupComparison& g : t.groups) {
    nlohmann::json metrics = nlohmann::json::array();
    bool regression = false;
    for (const MetricComparison& m : g.metrics) {
      metrics.push_back(metricJson(m, def));
      regression = regression || m.regression;
    }
    nlohmann::json episodes = nlohmann::json::array();
    std::vector<Pair>& members = pairs[g.name()];
    orderPairs(members);
    for (const auto& [id, b, c] : members) {
      nlohmann::json e = {{"id", id}, {"baseline", side(*b)}, {"candidate", side(*c)}};
      // Compared across columns, the candidate's episode has an id of its own.
      const std::string candidate_id = c->value("episode_id", "");
      if (candidate_id != id) e["candidate_id"] = candidate_id;
      episodes.push_back(std::move(e));
    }
    nlohmann::json group = {{"name", g.name()},
                            {"world", g.world},
                            {"planner", g.planner},
                            {"realism", g.realism},
                            {"paired", g.paired},
                            {"shared_ids", g.shared_ids},
                            {"baseline_rows", g.baseline_rows},
                            {"candidate_rows", g.candidate_rows},
                            {"regression", regression},
                            {"metrics", std::move(metrics)},
                            {"episodes", std::move(episodes)}};
    if (!g.across.empty()) {
      nlohmann::json across = nlohmann::json::array();
      for (const AcrossValues& a : g.across) {
        across.push_back(
            {{"column", a.column}, {"baseline", a.baseline}, {"candidate", a.candidate}});
      }
      group["across"] = std::move(across);
    }
    groups.push_back(std::move(group));
  }
  nlohmann::json out = {
      {"baseline", {{"path", sources.baseline}, {"rows", sources.baseline_rows}}},
      {"candidate", {{"path", sources.candidate}, {"rows", sources.candidate_rows}}},
      {"settings",
       {{"confidence", def.confidence},
        {"max_increase", def.max_increase},
        {"min_increase_m", def.min_increase_m},
        {"max_success_drop", def.max_success_drop},
        {"resamples", t.resamples},
        {"min_samples", def.min_samples},
        {"seed", def.seed}}},
      {"tests", t.tests},
      {"regressions", t.regressions},
      {"regression", t.regression()},
      {"only_baseline", t.only_baseline},
      {"only_candidate", t.only_candidate},
      {"groups", std::move(groups)}};
  if (!t.across.empty()) out["across"] = t.across;
  return out;
}

}  // namespace parksim
