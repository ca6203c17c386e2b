#pragma once
// Benchmark results in the text log format of OMPL's ompl::tools::Benchmark (as
// Benchmark::saveResultsToStream writes it in OMPL 1.5), so that ompl_benchmark_statistics.py
// and Planner Arena can read parksim's and OMPL's runs together. One log holds one experiment:
// write one per scenario. Every (library, planner, space, budget) group becomes a "planner" named
// `<library>_<planner>_<space>`, with `_<budget>` appended where one such name has several
// budgets. Run properties: time REAL (whole run), first solution time REAL, solved BOOLEAN,
// valid BOOLEAN, status ENUM (OMPL's PlannerStatus), solution length REAL, solution clearance
// REAL, cusps INTEGER, graph states INTEGER, iterations INTEGER, seed INTEGER. Missing values
// are left empty, as OMPL does. Records with a cost history (BenchRecord::progress) add the
// progress properties time REAL and best cost REAL, which Planner Arena plots over time.

#include <string>
#include <vector>

#include "parksim/results/reports/BenchRecord.h"

namespace parksim::bench {

struct OmplLogInfo {
  std::string experiment;   ///< experiment name, one token, e.g. "parksim_head_in"
  std::string host;         ///< machine name
  std::string start_time;   ///< e.g. "2024-06-11 09:47:25"
  std::string setup;        ///< free text: scenario, settings, command line
  std::string cpu_info;     ///< free text, may be empty
  double time_limit_s = 0;  ///< the longest budget of any run, s
  int runs_per_planner = 0;
  double total_s = 0;  ///< wall time spent collecting the data, s
};

/// The local time now in start_time's format.
std::string omplLogTimeNow();

/// The log text for `records` (all of one scenario).
std::string omplBenchmarkLog(const OmplLogInfo& info, const std::vector<BenchRecord>& records);

/// OMPL's PlannerStatus value for a record's status: OMPL's own names map to themselves;
/// parksim's "solved" to exact solution, iteration and time limits to timeout, invalid start
/// and goal to theirs; a failed child process to crash.
int omplStatusCode(const BenchRecord& record);

}  // namespace parksim::bench
