#pragma once
// bench.csv: one row per benchmark run. The fixed columns come first, in this order:
//   library,planner,space,scenario,seed,budget,solved,status,valid,time_first_s,time_total_s,
//   cpu_total_s,length_m,cusps,duration_s,duration_lower_bound_s,free_space_bound_s,
//   min_clearance_m,steering_reversals_per_m,cost,iterations,iterations_first,tree_size,
//   collision_queries
// then the provenance of the build that ran them (parksim/core/system/Provenance.h):
//   parksim_version,git_commit,git_dirty,build_type,compiler,bullet_precision
// followed by one `phase_<name>_s` column per planner phase any row reports. Units: s, m.
// Values a run does not have are left empty; booleans are 0 or 1.

#include <string>
#include <vector>

#include "parksim/core/system/Provenance.h"
#include "parksim/results/reports/BenchRecord.h"

namespace parksim::bench {

/// The column names for `records`, in file order.
std::vector<std::string> benchCsvColumns(const std::vector<BenchRecord>& records);

/// The whole file: header line and one line per record, each stamped with `provenance`.
std::string benchCsv(const std::vector<BenchRecord>& records,
                     const Provenance& provenance = buildProvenance());

/// Writes benchCsv(records) to `path` atomically. Throws Error when it cannot be written.
void writeBenchCsv(const std::string& path, const std::vector<BenchRecord>& records);

}  // namespace parksim::bench
