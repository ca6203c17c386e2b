#pragma once
// Issue 18's measure of plan quality: per world, each configuration's plan duration over the
// best duration any configuration found, and over the free-space optimum (the Balkcom-Mason
// bound with the acceleration ramps, FreeSpaceBound.h: no plan can be faster). "Best" is the
// shortest valid plan among the records given (one benchmark run), or a recorded best known
// duration (docs/benchmarks.md's portfolio) when that is shorter.

#include <map>
#include <string>
#include <vector>

#include "parksim/results/reports/BenchRecord.h"

namespace parksim::bench {

struct BestKnownRow {
  std::string scenario;
  std::string library;
  std::string planner;
  std::string space;
  std::string budget;
  int runs = 0;
  int solved = 0;
  int valid = 0;
  double duration_median_s = kNotMeasured;  ///< over valid solved runs
  double best_s = kNotMeasured;             ///< the scenario's best known duration
  double over_best = kNotMeasured;          ///< duration_median_s / best_s
  double free_space_bound_s = kNotMeasured;
  double over_free_space = kNotMeasured;  ///< duration_median_s / free_space_bound_s
  /// Changes of turning direction per metre (PlanShape.h), median over valid solved runs, 1/m.
  double reversals_per_m_median = kNotMeasured;
  double time_total_median_s = kNotMeasured;  ///< planning wall time, median over runs
  double cpu_total_median_s = kNotMeasured;   ///< planning CPU time, median over runs
};

/// The shortest duration of a valid solved record per scenario.
std::map<std::string, double> bestDurations(const std::vector<BenchRecord>& records);

/// One row per (scenario, library, planner, space, budget), in first-seen order, measured
/// against the best of bestDurations(records) and `recorded` (scenario -> duration, s).
std::vector<BestKnownRow> compareWithBest(const std::vector<BenchRecord>& records,
                                          const std::map<std::string, double>& recorded = {});

/// The rows as a Markdown table: scenario, planner, space, budget, solved, valid, duration
/// median, best known, duration / best, free-space bound, duration / free-space bound, steering
/// reversals per metre, planning time median (wall and CPU).
std::string formatBestKnownTable(const std::vector<BestKnownRow>& rows);

}  // namespace parksim::bench
