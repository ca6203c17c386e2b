#pragma once
// Statistics of benchmark runs per library, planner, space, scenario and budget, the tables the
// bench command prints (GitHub-flavoured Markdown, readable as plain text too), and the
// comparisons the issue-5 targets ask for.
//
// Times to first solution count unsolved runs as infinitely slow: a median or p90 that lands on
// an unsolved run shows as "unsolved" rather than hiding the failures behind the solved runs.
// Path length, cusps and clearance are medians over solved runs.

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "parksim/results/reports/BenchRecord.h"

namespace parksim::bench {

struct GroupSummary {
  std::string library;
  std::string planner;
  std::string space;
  std::string scenario;
  std::string budget;
  int runs = 0;
  int solved = 0;
  int valid = 0;  ///< solved runs whose path passed parksim's exact check
  double time_first_median_s = kNotMeasured;
  double time_first_p90_s = kNotMeasured;
  double length_median_m = kNotMeasured;
  double cusps_median = kNotMeasured;
  double duration_median_s = kNotMeasured;  ///< planned trajectory's duration (parksim)
  /// Median over solved runs of duration / its lower bound (parksim).
  double duration_ratio_median = kNotMeasured;
  double clearance_median_m = kNotMeasured;
  double time_total_mean_s = kNotMeasured;
  double cpu_total_median_s = kNotMeasured;  ///< median CPU time of a whole run
  /// Mean over runs of each phase, s, in the planner's order (parksim only).
  std::vector<std::pair<std::string, double>> phase_mean_s;

  double successRate() const { return runs > 0 ? static_cast<double>(solved) / runs : 0.0; }
};

/// Groups `records` by (library, planner, space, scenario, budget), in first-seen order.
std::vector<GroupSummary> summarize(const std::vector<BenchRecord>& records);

/// Linear-interpolation quantile (q in [0, 1]) of `values`; +infinity entries sort last.
/// NaN when `values` is empty.
double quantile(std::vector<double> values, double q);

/// The study's own planning time for a parksim planner on a scenario, s, measured by
/// re-running its Python notebook on a 2-core machine (/work/shared/reference/README.md):
/// improved RRT (rrt-goal-connect) 40.0 s head_in and 101.6 s parallel, basic RRT (rrt)
/// 27.5 s head_in. Empty when the study has no figure.
std::optional<double> studyPlanningTime(const std::string& scenario, const std::string& planner);

/// Success, time to first solution, length, cusps, clearance per group; the study's figure
/// beside the parksim planners that have one.
std::string formatSummaryTable(const std::vector<GroupSummary>& groups);

/// Where parksim's planners spend their time: mean ms per phase and share of the total.
std::string formatPhaseTable(const std::vector<GroupSummary>& groups);

/// Per scenario, the issue-5 comparisons, each with its ratio and verdict:
/// time to first solution of parksim's fastest planner (iteration-budgeted runs; "+smooth"
/// variants are left out, their first solution being the unsmoothed one) vs OMPL's fastest
/// Reeds-Shepp planner, preferring planners that solved every run (with several steering
/// functions, also the fastest per steering function); and path length of each of
/// parksim's time-budgeted (anytime) runs vs OMPL's RRTstar (Reeds-Shepp). The time target is
/// met when parksim's median is no larger, it solved every run and every path passed the check.
std::string formatComparison(const std::vector<GroupSummary>& groups);

}  // namespace parksim::bench
