// bench.csv: the required columns in order, phase columns, empty cells for missing values.

#include "bench/planning/BenchCsv.h"

#include <gtest/gtest.h>

#include <sstream>

namespace parksim::bench {
namespace {

std::vector<std::string> splitLines(const std::string& text) {
  std::vector<std::string> lines;
  std::stringstream ss(text);
  for (std::string line; std::getline(ss, line);) lines.push_back(line);
  return lines;
}

BenchRecord parksimRecord() {
  BenchRecord r;
  r.library = "parksim";
  r.planner = "rrt-goal-connect";
  r.space = "move-to-pose";
  r.scenario = "head_in";
  r.seed = 7;
  r.budget = "iterations=2000";
  r.solved = true;
  r.status = "solved";
  r.valid = true;
  r.time_first_s = 0.25;
  r.time_total_s = 0.25;
  r.cpu_total_s = 0.2;
  r.length_m = 1.5;
  r.cusps = 2;
  r.min_clearance_m = 0.004;
  r.cost = 1.6;
  r.iterations = 40;
  r.iterations_first = 12;
  r.tree_size = 30;
  r.collision_queries = 1000;
  r.phases_s = {{"sampling", 0.01}, {"total", 0.25}};
  return r;
}

BenchRecord unsolvedOmplRecord() {
  BenchRecord r;
  r.library = "ompl";
  r.planner = "RRT";
  r.space = "reeds-shepp";
  r.scenario = "head_in";
  r.seed = 7;
  r.budget = "time=1s";
  r.status = "Timeout";
  r.time_total_s = 1.0;
  r.tree_size = 5000;
  return r;
}

TEST(BenchCsv, HeaderStartsWithTheRequiredColumns) {
  const std::string csv = benchCsv({parksimRecord(), unsolvedOmplRecord()});
  const std::vector<std::string> lines = splitLines(csv);
  ASSERT_EQ(lines.size(), 3u);
  EXPECT_EQ(lines[0],
            "library,planner,space,scenario,seed,budget,solved,status,valid,time_first_s,"
            "time_total_s,cpu_total_s,length_m,cusps,duration_s,duration_lower_bound_s,"
            "free_space_bound_s,"
            "min_clearance_m,steering_reversals_per_m,cost,iterations,"
            "iterations_first,tree_size,collision_queries,parksim_version,git_commit,git_dirty,"
            "build_type,compiler,bullet_precision,phase_sampling_s,phase_total_s");
  // The required columns, in its order, are all there.
  std::vector<std::string> required = {"library",  "planner", "scenario",
                                       "seed",     "solved",  "time_first_s",
                                       "length_m", "cusps",   "min_clearance_m"};
  const std::vector<std::string> columns = benchCsvColumns({parksimRecord()});
  std::size_t at = 0;
  for (const std::string& name : required) {
    while (at < columns.size() && columns[at] != name) ++at;
    EXPECT_LT(at, columns.size()) << name;
  }
}

Provenance someBuild() {
  Provenance p;
  p.version = "9.8.7";
  p.git_commit = "0123456789abcdef0123456789abcdef01234567";
  p.git_dirty = true;
  p.build_type = "Release";
  p.compiler = "GNU 12.2.0";
  p.bullet_precision = "double";
  return p;
}

TEST(BenchCsv, RowsCarryValuesAndLeaveMissingOnesEmpty) {
  const std::vector<std::string> lines =
      splitLines(benchCsv({parksimRecord(), unsolvedOmplRecord()}, someBuild()));
  const std::string build =
      "9.8.7,0123456789abcdef0123456789abcdef01234567,true,Release,GNU 12.2.0,double";
  EXPECT_EQ(lines[1],
            "parksim,rrt-goal-connect,move-to-pose,head_in,7,iterations=2000,1,solved,1,0.25,0.25,"
            "0.2,1.5,2,,,,0.004,,1.6,40,12,30,1000," +
                build + ",0.01,0.25");
  EXPECT_EQ(lines[2], "ompl,RRT,reeds-shepp,head_in,7,time=1s,0,Timeout,0,,1,,,,,,,,,,,,5000,," +
                          build + ",,");
}

TEST(BenchCsv, TextWithCommasIsQuoted) {
  BenchRecord r = unsolvedOmplRecord();
  r.status = "child error: a, b";
  const std::vector<std::string> lines = splitLines(benchCsv({r}));
  EXPECT_NE(lines[1].find(",\"child error: a, b\","), std::string::npos);
}

}  // namespace
}  // namespace parksim::bench
