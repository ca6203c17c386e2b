#include "bench/planning/BenchSummary.h"
#include "parksim/core/io/NumberFormat.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <tuple>

namespace parksim::bench {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

std::string fixed(double v, int decimals) { return formatFixed(v, decimals); }

std::string timeText(double s) {
  if (std::isnan(s)) return "-";
  if (std::isinf(s)) return "unsolved";
  const double ms = 1e3 * s;
  if (ms < 10.0) return fixed(ms, 3) + " ms";
  if (ms < 1000.0) return fixed(ms, 1) + " ms";
  return fixed(s, 2) + " s";
}

std::string lengthText(double m) { return std::isnan(m) ? "-" : fixed(m, 3) + " m"; }
std::string mmText(double m) { return std::isnan(m) ? "-" : fixed(1e3 * m, 1) + " mm"; }
std::string plainText(double v) { return std::isnan(v) ? "-" : formatGeneral(v); }
std::string percentText(double share) { return fixed(100.0 * share, 0) + "%"; }

// A GitHub-flavoured Markdown table with padded columns.
std::string markdownTable(const std::vector<std::string>& header,
                          const std::vector<std::vector<std::string>>& rows) {
  std::vector<std::size_t> width(header.size(), 3);
  for (std::size_t c = 0; c < header.size(); ++c) width[c] = std::max(width[c], header[c].size());
  for (const auto& row : rows) {
    for (std::size_t c = 0; c < row.size() && c < width.size(); ++c) {
      width[c] = std::max(width[c], row[c].size());
    }
  }
  auto line = [&](const std::vector<std::string>& cells) {
    std::string out = "|";
    for (std::size_t c = 0; c < width.size(); ++c) {
      const std::string cell = c < cells.size() ? cells[c] : "";
      out += " " + cell + std::string(width[c] - cell.size(), ' ') + " |";
    }
    return out + "\n";
  };
  std::string out = line(header);
  out += "|";
  for (std::size_t w : width) out += std::string(w + 2, '-') + "|";
  out += "\n";
  for (const auto& row : rows) out += line(row);
  return out;
}

bool isTimeBudgeted(const GroupSummary& g) { return g.budget.find("time=") != std::string::npos; }

bool isSmoothed(const GroupSummary& g) { return g.planner.find("+smooth") != std::string::npos; }

std::string label(const GroupSummary& g) {
  return g.library + " " + g.planner + " (" + g.space + ", " + g.budget + ")";
}

// The group with the smallest median time to first solution, preferring groups that solved
// every run; nullptr when there is none.
const GroupSummary* fastest(const std::vector<const GroupSummary*>& candidates) {
  const GroupSummary* best = nullptr;
  auto key = [](const GroupSummary* g) {
    return std::make_tuple(g->solved < g->runs, g->time_first_median_s);
  };
  for (const GroupSummary* g : candidates) {
    if (std::isnan(g->time_first_median_s)) continue;
    if (best == nullptr || key(g) < key(best)) best = g;
  }
  return best;
}

}  // namespace

double quantile(std::vector<double> values, double q) {
  if (values.empty()) return kNotMeasured;
  std::sort(values.begin(), values.end());
  const double h = q * static_cast<double>(values.size() - 1);
  const auto lo = static_cast<std::size_t>(std::floor(h));
  const double frac = h - static_cast<double>(lo);
  if (frac == 0.0 || lo + 1 >= values.size()) return values[lo];
  if (std::isinf(values[lo + 1])) return kInf;  // interpolating towards an unsolved run
  return values[lo] + frac * (values[lo + 1] - values[lo]);
}

std::optional<double> studyPlanningTime(const std::string& scenario, const std::string& planner) {
  if (scenario == "head_in" && planner == "rrt-goal-connect") return 40.0;
  if (scenario == "parallel" && planner == "rrt-goal-connect") return 101.6;
  if (scenario == "head_in" && planner == "rrt") return 27.5;
  return std::nullopt;
}

std::vector<GroupSummary> summarize(const std::vector<BenchRecord>& records) {
  struct Acc {
    GroupSummary g;
    std::vector<double> times, lengths, cusps, clearances, totals, cpus, durations, ratios;
    std::vector<std::pair<std::string, double>> phase_sum;
  };
  std::vector<Acc> accs;
  for (const BenchRecord& r : records) {
    auto it = std::find_if(accs.begin(), accs.end(), [&](const Acc& a) {
      return a.g.library == r.library && a.g.planner == r.planner && a.g.space == r.space &&
             a.g.scenario == r.scenario && a.g.budget == r.budget;
    });
    if (it == accs.end()) {
      accs.push_back({});
      it = std::prev(accs.end());
      it->g.library = r.library;
      it->g.planner = r.planner;
      it->g.space = r.space;
      it->g.scenario = r.scenario;
      it->g.budget = r.budget;
    }
    Acc& a = *it;
    ++a.g.runs;
    a.times.push_back(r.solved && !std::isnan(r.time_first_s) ? r.time_first_s : kInf);
    if (!std::isnan(r.time_total_s)) a.totals.push_back(r.time_total_s);
    if (!std::isnan(r.cpu_total_s)) a.cpus.push_back(r.cpu_total_s);
    if (r.solved) {
      ++a.g.solved;
      if (r.valid) ++a.g.valid;
      if (!std::isnan(r.length_m)) a.lengths.push_back(r.length_m);
      if (r.cusps >= 0) a.cusps.push_back(r.cusps);
      if (!std::isnan(r.duration_s)) a.durations.push_back(r.duration_s);
      if (!std::isnan(r.duration_s) && r.duration_lower_bound_s > 0.0) {
        a.ratios.push_back(r.duration_s / r.duration_lower_bound_s);
      }
      if (!std::isnan(r.min_clearance_m)) a.clearances.push_back(r.min_clearance_m);
    }
    // A named pair, not a structured binding: clang before 16 cannot capture bindings.
    for (const auto& phase : r.phases_s) {
      auto p = std::find_if(a.phase_sum.begin(), a.phase_sum.end(),
                            [&](const auto& e) { return e.first == phase.first; });
      if (p == a.phase_sum.end()) {
        a.phase_sum.push_back(phase);
      } else {
        p->second += phase.second;
      }
    }
  }
  std::vector<GroupSummary> groups;
  for (Acc& a : accs) {
    GroupSummary g = a.g;
    g.time_first_median_s = quantile(a.times, 0.5);
    g.time_first_p90_s = quantile(a.times, 0.9);
    g.length_median_m = quantile(a.lengths, 0.5);
    g.cusps_median = quantile(a.cusps, 0.5);
    g.duration_median_s = quantile(a.durations, 0.5);
    g.duration_ratio_median = quantile(a.ratios, 0.5);
    g.clearance_median_m = quantile(a.clearances, 0.5);
    g.cpu_total_median_s = quantile(a.cpus, 0.5);
    if (!a.totals.empty()) {
      double sum = 0.0;
      for (double t : a.totals) sum += t;
      g.time_total_mean_s = sum / static_cast<double>(a.totals.size());
    }
    for (const auto& [name, sum] : a.phase_sum) {
      g.phase_mean_s.emplace_back(name, sum / g.runs);
    }
    groups.push_back(std::move(g));
  }
  return groups;
}

std::string formatSummaryTable(const std::vector<GroupSummary>& groups) {
  const std::vector<std::string> header = {"scenario",
                                           "library",
                                           "planner",
                                           "space",
                                           "budget",
                                           "runs",
                                           "solved",
                                           "valid",
                                           "t_first median",
                                           "t_first p90",
                                           "CPU per run median",
                                           "length median",
                                           "cusps median",
                                           "duration median",
                                           "duration / bound median",
                                           "clearance median",
                                           "study (Python)"};
  std::vector<std::vector<std::string>> rows;
  for (const GroupSummary& g : groups) {
    std::string study = "";
    if (g.library == "parksim") {
      if (const auto s = studyPlanningTime(g.scenario, g.planner)) {
        study = fixed(*s, 1) + " s";
        if (std::isfinite(g.time_first_median_s) && g.time_first_median_s > 0.0) {
          study += " = " + fixed(*s / g.time_first_median_s, 0) + "x parksim's median";
        }
      }
    }
    rows.push_back({g.scenario, g.library, g.planner, g.space, g.budget, std::to_string(g.runs),
                    percentText(g.successRate()),
                    g.solved > 0 ? fixed(100.0 * g.valid / g.solved, 0) + "%" : "-",
                    timeText(g.time_first_median_s), timeText(g.time_first_p90_s),
                    timeText(g.cpu_total_median_s), lengthText(g.length_median_m),
                    plainText(g.cusps_median),
                    std::isnan(g.duration_median_s) ? "-" : fixed(g.duration_median_s, 1) + " s",
                    std::isnan(g.duration_ratio_median) ? "-" : fixed(g.duration_ratio_median, 2),
                    mmText(g.clearance_median_m), study});
  }
  return markdownTable(header, rows);
}

std::string formatPhaseTable(const std::vector<GroupSummary>& groups) {
  std::vector<std::string> phases;  // every phase but the total, in the planners' order
  for (const GroupSummary& g : groups) {
    for (const auto& [name, s] : g.phase_mean_s) {
      if (name != "total" && std::find(phases.begin(), phases.end(), name) == phases.end()) {
        phases.push_back(name);
      }
    }
  }
  std::vector<std::string> header = {"scenario", "planner", "space", "budget", "mean total"};
  for (const std::string& p : phases) header.push_back(p);
  header.push_back("other");
  std::vector<std::vector<std::string>> rows;
  for (const GroupSummary& g : groups) {
    if (g.phase_mean_s.empty()) continue;
    double total = 0.0;
    for (const auto& [name, s] : g.phase_mean_s) {
      if (name == "total") total = s;
    }
    std::vector<std::string> row = {g.scenario, g.planner, g.space, g.budget, timeText(total)};
    double accounted = 0.0;
    for (const std::string& p : phases) {
      std::string cell = "-";
      for (const auto& [name, s] : g.phase_mean_s) {
        if (name != p) continue;
        accounted += s;
        cell = timeText(s) + (total > 0.0 ? " (" + percentText(s / total) + ")" : "");
      }
      row.push_back(cell);
    }
    const double other = std::max(0.0, total - accounted);
    row.push_back(timeText(other) + (total > 0.0 ? " (" + percentText(other / total) + ")" : ""));
    rows.push_back(std::move(row));
  }
  return markdownTable(header, rows);
}

std::string formatComparison(const std::vector<GroupSummary>& groups) {
  std::vector<std::string> scenarios;
  for (const GroupSummary& g : groups) {
    if (std::find(scenarios.begin(), scenarios.end(), g.scenario) == scenarios.end()) {
      scenarios.push_back(g.scenario);
    }
  }
  const std::vector<std::string> header = {"scenario", "measure",        "parksim",
                                           "OMPL",     "parksim / OMPL", "target met"};
  std::vector<std::vector<std::string>> rows;
  for (const std::string& scenario : scenarios) {
    std::vector<const GroupSummary*> parksim_first, parksim_anytime, ompl_drivable, ompl_star;
    for (const GroupSummary& g : groups) {
      if (g.scenario != scenario) continue;
      if (g.library == "parksim") {
        if (isTimeBudgeted(g)) {
          parksim_anytime.push_back(&g);
        } else if (!isSmoothed(g)) {
          // Smoothing starts after the first solution, which it leaves as it is.
          parksim_first.push_back(&g);
        }
      } else if (g.library == "ompl" && g.space == "reeds-shepp") {
        ompl_drivable.push_back(&g);
        if (g.planner == "RRTstar") ompl_star.push_back(&g);
      }
    }
    // The fastest of all, then the fastest per steering function when there are several: one
    // steering function can make a query trivial, and the other's figure should stay visible.
    std::vector<std::pair<std::string, const GroupSummary*>> contenders = {
        {"time to first solution, median", fastest(parksim_first)}};
    std::vector<std::string> spaces;
    for (const GroupSummary* g : parksim_first) {
      if (std::find(spaces.begin(), spaces.end(), g->space) == spaces.end()) {
        spaces.push_back(g->space);
      }
    }
    for (const std::string& space : spaces) {
      if (spaces.size() < 2) break;
      std::vector<const GroupSummary*> mine;
      for (const GroupSummary* g : parksim_first) {
        if (g->space == space) mine.push_back(g);
      }
      contenders.emplace_back("same, best " + space + " planner", fastest(mine));
    }
    const GroupSummary* o = fastest(ompl_drivable);
    for (const auto& [measure, p] : contenders) {
      if (p == nullptr || o == nullptr) continue;
      const double ratio = p->time_first_median_s / o->time_first_median_s;
      const bool met = p->solved == p->runs && p->valid == p->solved &&
                       p->time_first_median_s <= o->time_first_median_s;
      rows.push_back({scenario, measure,
                      label(*p) + ": " + timeText(p->time_first_median_s) + ", " +
                          percentText(p->successRate()) + " solved",
                      label(*o) + ": " + timeText(o->time_first_median_s) + ", " +
                          percentText(o->successRate()) + " solved",
                      std::isfinite(ratio) ? formatGeneral(ratio, 3) : "-", met ? "yes" : "NO"});
    }
    for (const GroupSummary* a : parksim_anytime) {
      for (const GroupSummary* s : ompl_star) {
        const double ratio = a->length_median_m / s->length_median_m;
        const bool met = a->solved == a->runs && a->length_median_m <= s->length_median_m;
        rows.push_back({scenario, "path length, median",
                        label(*a) + ": " + lengthText(a->length_median_m) + ", " +
                            percentText(a->successRate()) + " solved",
                        label(*s) + ": " + lengthText(s->length_median_m) + ", " +
                            percentText(s->successRate()) + " solved",
                        std::isfinite(ratio) ? formatGeneral(ratio, 3) : "-", met ? "yes" : "NO"});
      }
    }
  }
  if (rows.empty()) return "";
  return markdownTable(header, rows);
}

}  // namespace parksim::bench
