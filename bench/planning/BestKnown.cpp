#include "bench/planning/BestKnown.h"

#include <algorithm>
#include <cmath>

#include "bench/planning/BenchSummary.h"
#include "parksim/core/io/NumberFormat.h"

namespace parksim::bench {

namespace {

std::string number(double v, int decimals) {
  return std::isnan(v) ? "-" : formatFixed(v, decimals);
}

std::string milliseconds(double s) { return std::isnan(s) ? "-" : formatFixed(1e3 * s, 1) + " ms"; }

}  // namespace

std::map<std::string, double> bestDurations(const std::vector<BenchRecord>& records) {
  std::map<std::string, double> best;
  for (const BenchRecord& r : records) {
    if (!r.solved || !r.valid || std::isnan(r.duration_s)) continue;
    const auto it = best.find(r.scenario);
    if (it == best.end() || r.duration_s < it->second) best[r.scenario] = r.duration_s;
  }
  return best;
}

std::vector<BestKnownRow> compareWithBest(const std::vector<BenchRecord>& records,
                                          const std::map<std::string, double>& recorded) {
  std::map<std::string, double> best = bestDurations(records);
  for (const auto& [scenario, duration] : recorded) {
    const auto it = best.find(scenario);
    if (it == best.end() || duration < it->second) best[scenario] = duration;
  }
  struct Acc {
    BestKnownRow row;
    std::vector<double> durations, bounds, totals, cpus, reversals;
  };
  std::vector<Acc> accs;
  for (const BenchRecord& r : records) {
    auto it = std::find_if(accs.begin(), accs.end(), [&](const Acc& a) {
      return a.row.scenario == r.scenario && a.row.library == r.library &&
             a.row.planner == r.planner && a.row.space == r.space && a.row.budget == r.budget;
    });
    if (it == accs.end()) {
      accs.push_back({});
      it = std::prev(accs.end());
      it->row = {r.scenario, r.library, r.planner, r.space, r.budget};
    }
    Acc& a = *it;
    ++a.row.runs;
    if (!std::isnan(r.time_total_s)) a.totals.push_back(r.time_total_s);
    if (!std::isnan(r.cpu_total_s)) a.cpus.push_back(r.cpu_total_s);
    if (!r.solved) continue;
    ++a.row.solved;
    if (!r.valid) continue;
    ++a.row.valid;
    if (!std::isnan(r.duration_s)) a.durations.push_back(r.duration_s);
    if (r.free_space_bound_s > 0.0) a.bounds.push_back(r.free_space_bound_s);
    if (!std::isnan(r.steering_reversals_per_m)) a.reversals.push_back(r.steering_reversals_per_m);
  }
  std::vector<BestKnownRow> rows;
  for (Acc& a : accs) {
    BestKnownRow& row = a.row;
    row.duration_median_s = quantile(a.durations, 0.5);
    row.time_total_median_s = quantile(a.totals, 0.5);
    row.cpu_total_median_s = quantile(a.cpus, 0.5);
    row.free_space_bound_s = quantile(a.bounds, 0.5);
    row.reversals_per_m_median = quantile(a.reversals, 0.5);
    if (const auto it = best.find(row.scenario); it != best.end()) {
      row.best_s = it->second;
      row.over_best = row.duration_median_s / row.best_s;
    }
    if (row.free_space_bound_s > 0.0) {
      row.over_free_space = row.duration_median_s / row.free_space_bound_s;
    }
    rows.push_back(row);
  }
  return rows;
}

std::string formatBestKnownTable(const std::vector<BestKnownRow>& rows) {
  std::string out =
      "| scenario | library | planner | space | budget | solved | valid | duration median | "
      "best known | duration / best | free-space bound | duration / free-space bound | "
      "reversals / m | planning time median | CPU median |\n"
      "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const BestKnownRow& r : rows) {
    const std::string solved = std::to_string(r.solved) + "/" + std::to_string(r.runs);
    const std::string valid = std::to_string(r.valid) + "/" + std::to_string(r.solved);
    out += "| " + r.scenario + " | " + r.library + " | " + r.planner + " | " + r.space + " | " +
           r.budget + " | " + solved + " | " + valid + " | " + number(r.duration_median_s, 2) +
           " s | " + number(r.best_s, 2) + " s | " + number(r.over_best, 3) + " | " +
           number(r.free_space_bound_s, 2) + " s | " + number(r.over_free_space, 3) + " | " +
           number(r.reversals_per_m_median, 2) + " | " + milliseconds(r.time_total_median_s) +
           " | " + milliseconds(r.cpu_total_median_s) + " |\n";
  }
  return out;
}

}  // namespace parksim::bench
