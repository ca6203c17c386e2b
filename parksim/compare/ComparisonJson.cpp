#include "parksim/compare/ComparisonJson.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <tuple>

#include "parksim/sweep/Report.h"

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

// Episodes of both tables by group name: (id, baseline row, candidate row).
using Pair = std::tuple<std::string, const Json*, const Json*>;

std::map<std::string, std::vector<Pair>> pairsByGroup(const std::vector<Json>& baseline,
                                                      const std::vector<Json>& candidate) {
  std::map<std::string, const Json*> by_id;
  for (const Json& row : candidate) by_id.emplace(row.value("episode_id", ""), &row);
  std::map<std::string, std::vector<Pair>> groups;
  for (const Json& row : baseline) {
    const std::string id = row.value("episode_id", "");
    const auto it = by_id.find(id);
    if (id.empty() || it == by_id.end()) continue;
    groups[rowGroupName(rowGroupKey(row))].emplace_back(id, &row, it->second);
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
  std::map<std::string, std::vector<Pair>> pairs = pairsByGroup(baseline, candidate);
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
      episodes.push_back({{"id", id}, {"baseline", side(*b)}, {"candidate", side(*c)}});
    }
    groups.push_back({{"name", g.name()},
                      {"world", g.world},
                      {"planner", g.planner},
                      {"realism", g.realism},
                      {"paired", g.paired},
                      {"shared_ids", g.shared_ids},
                      {"baseline_rows", g.baseline_rows},
                      {"candidate_rows", g.candidate_rows},
                      {"regression", regression},
                      {"metrics", std::move(metrics)},
                      {"episodes", std::move(episodes)}});
  }
  return {{"baseline", {{"path", sources.baseline}, {"rows", sources.baseline_rows}}},
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
}

}  // namespace parksim
