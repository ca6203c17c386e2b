#include "bench/planning/BenchCsv.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "parksim/core/io/AtomicFile.h"
#include "parksim/core/io/Csv.h"
#include "parksim/core/io/NumberFormat.h"

namespace parksim::bench {
namespace {

const char* const kFixedColumns[] = {"library",
                                     "planner",
                                     "space",
                                     "scenario",
                                     "seed",
                                     "budget",
                                     "solved",
                                     "status",
                                     "valid",
                                     "time_first_s",
                                     "time_total_s",
                                     "cpu_total_s",
                                     "length_m",
                                     "cusps",
                                     "duration_s",
                                     "duration_lower_bound_s",
                                     "free_space_bound_s",
                                     "min_clearance_m",
                                     "steering_reversals_per_m",
                                     "cost",
                                     "iterations",
                                     "iterations_first",
                                     "tree_size",
                                     "collision_queries"};

// Phase names in first-seen order, so the columns follow the planner's own phase order.
std::vector<std::string> phaseNames(const std::vector<BenchRecord>& records) {
  std::vector<std::string> names;
  for (const BenchRecord& r : records) {
    for (const auto& [name, seconds] : r.phases_s) {
      if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
    }
  }
  return names;
}

std::string number(double v) {
  if (std::isnan(v)) return "";
  return formatGeneral(v, 9);
}

std::string count(long v) { return v < 0 ? "" : std::to_string(v); }

// Text fields are names chosen by parksim and OMPL; quote them anyway if they ever hold a comma.
std::string text(const std::string& s) { return csvField(s); }

}  // namespace

std::vector<std::string> benchCsvColumns(const std::vector<BenchRecord>& records) {
  std::vector<std::string> columns(std::begin(kFixedColumns), std::end(kFixedColumns));
  for (const auto& [key, value] : provenanceFields(Provenance{})) columns.push_back(key);
  for (const std::string& name : phaseNames(records)) columns.push_back("phase_" + name + "_s");
  return columns;
}

std::string benchCsv(const std::vector<BenchRecord>& records, const Provenance& provenance) {
  std::string out;
  const std::vector<std::string> columns = benchCsvColumns(records);
  for (std::size_t i = 0; i < columns.size(); ++i) out += (i ? "," : "") + columns[i];
  out += '\n';
  const std::vector<std::string> phases = phaseNames(records);
  std::string stamp;
  for (const auto& [key, value] : provenanceFields(provenance)) {
    stamp += ',';  // appended alone: `"," + std::string` trips GCC 12's false -Wrestrict
    stamp += text(value);
  }
  for (const BenchRecord& r : records) {
    const std::vector<std::string> fields = {text(r.library),
                                             text(r.planner),
                                             text(r.space),
                                             text(r.scenario),
                                             std::to_string(r.seed),
                                             text(r.budget),
                                             r.solved ? "1" : "0",
                                             text(r.status),
                                             r.valid ? "1" : "0",
                                             number(r.time_first_s),
                                             number(r.time_total_s),
                                             number(r.cpu_total_s),
                                             number(r.length_m),
                                             count(r.cusps),
                                             number(r.duration_s),
                                             number(r.duration_lower_bound_s),
                                             number(r.free_space_bound_s),
                                             number(r.min_clearance_m),
                                             number(r.steering_reversals_per_m),
                                             number(r.cost),
                                             count(r.iterations),
                                             count(r.iterations_first),
                                             count(r.tree_size),
                                             count(r.collision_queries)};
    for (std::size_t i = 0; i < fields.size(); ++i) out += (i ? "," : "") + fields[i];
    out += stamp;
    for (const std::string& name : phases) {
      out += ',';
      for (const auto& [phase, seconds] : r.phases_s) {
        if (phase == name) out += number(seconds);
      }
    }
    out += '\n';
  }
  return out;
}

void writeBenchCsv(const std::string& path, const std::vector<BenchRecord>& records) {
  writeFileAtomically(path, benchCsv(records));
}

}  // namespace parksim::bench
