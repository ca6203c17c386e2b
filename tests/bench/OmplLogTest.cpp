// OMPL's benchmark log format: the header lines ompl_benchmark_statistics.py reads, one
// planner block per group, every run line with one value per property.

#include "parksim/core/system/Provenance.h"
#include "parksim/results/reports/OmplLog.h"

#include <gtest/gtest.h>

#include <sstream>

namespace parksim::bench {
// Named, not anonymous: its program is compiled as one unity batch, where another file's
// helpers of the same names would meet these.
namespace ompl_log_test {

std::vector<std::string> splitLines(const std::string& text) {
  std::vector<std::string> lines;
  std::stringstream ss(text);
  for (std::string line; std::getline(ss, line);) lines.push_back(line);
  return lines;
}

BenchRecord record(const std::string& library, const std::string& planner,
                   const std::string& budget, bool solved, const std::string& status) {
  BenchRecord r;
  r.library = library;
  r.planner = planner;
  r.space = library == "ompl" ? "reeds-shepp" : "move-to-pose";
  r.scenario = "head_in";
  r.seed = 1;
  r.budget = budget;
  r.solved = solved;
  r.valid = solved;
  r.status = status;
  r.time_first_s = solved ? 0.01 : kNotMeasured;
  r.time_total_s = 0.02;
  r.length_m = solved ? 1.7 : kNotMeasured;
  return r;
}

TEST(OmplLog, FollowsOmplsLayout) {
  OmplLogInfo info;
  info.experiment = "parksim_head_in";
  info.host = "box";
  info.start_time = "2024-06-11 09:47:25";
  info.setup = "scenario head_in\nseeds 1..2";
  info.time_limit_s = 1.0;
  info.runs_per_planner = 2;
  info.total_s = 3.5;
  const std::vector<BenchRecord> records = {
      record("parksim", "rrt-star", "iterations=2000", true, "solved"),
      record("parksim", "rrt-star", "time=0.1s", true, "solved"),
      record("ompl", "RRT", "time=1s", false, "Timeout"),
      record("ompl", "RRT", "time=1s", true, "Exact solution"),
  };
  const std::vector<std::string> lines = splitLines(omplBenchmarkLog(info, records));
  ASSERT_GT(lines.size(), 20u);
  std::size_t i = 0;
  EXPECT_EQ(lines[i++], "parksim version " + parksim::buildProvenance().version);
  EXPECT_EQ(lines[i++], "Experiment parksim_head_in");
  EXPECT_EQ(lines[i++], "0 experiment properties");
  EXPECT_EQ(lines[i++], "Running on box");
  EXPECT_EQ(lines[i++], "Starting at 2024-06-11 09:47:25");
  EXPECT_EQ(lines[i++], "<<<|");
  EXPECT_EQ(lines[i++], "scenario head_in");
  EXPECT_EQ(lines[i++], "seeds 1..2");
  EXPECT_EQ(lines[i++], "|>>>");
  EXPECT_EQ(lines[i++], "<<<|");
  EXPECT_EQ(lines[i++], "|>>>");
  EXPECT_EQ(lines[i++], "0 is the random seed");
  EXPECT_EQ(lines[i++], "1 seconds per run");
  EXPECT_EQ(lines[i++], "0 MB per run");
  EXPECT_EQ(lines[i++], "2 runs per planner");
  EXPECT_EQ(lines[i++], "3.5 seconds spent to collect the data");
  EXPECT_EQ(lines[i++], "1 enum type");
  EXPECT_EQ(lines[i++].rfind("status|Unknown status|Invalid start|", 0), 0u);
  EXPECT_EQ(lines[i++], "3 planners");

  // Same name with two budgets: the budget disambiguates.
  const std::vector<std::string> names = {"parksim_rrt-star_move-to-pose_iterations=2000",
                                          "parksim_rrt-star_move-to-pose_time=0.1s",
                                          "ompl_RRT_reeds-shepp"};
  for (const std::string& name : names) {
    ASSERT_LT(i, lines.size());
    EXPECT_EQ(lines[i++], name);
    ASSERT_EQ(lines[i++], "3 common properties");
    i += 3;
    const int properties = std::stoi(lines[i++]);
    EXPECT_EQ(properties, 11);
    i += static_cast<std::size_t>(properties);
    const int runs = std::stoi(lines[i++]);
    for (int r = 0; r < runs; ++r) {
      const std::string& line = lines[i++];
      std::size_t separators = 0;
      for (std::size_t at = line.find("; "); at != std::string::npos;
           at = line.find("; ", at + 2)) {
        ++separators;
      }
      EXPECT_EQ(separators, static_cast<std::size_t>(properties)) << line;
    }
    EXPECT_EQ(lines[i++], ".");
  }
  EXPECT_EQ(i, lines.size());
}

TEST(OmplLog, StatusCodesFollowOmplsEnum) {
  EXPECT_EQ(omplStatusCode(record("parksim", "rrt", "i", true, "solved")), 6);
  EXPECT_EQ(omplStatusCode(record("parksim", "rrt", "i", false, "iteration_limit")), 4);
  EXPECT_EQ(omplStatusCode(record("ompl", "RRT", "t", false, "Timeout")), 4);
  EXPECT_EQ(omplStatusCode(record("ompl", "RRT", "t", false, "Approximate solution")), 5);
  EXPECT_EQ(omplStatusCode(record("ompl", "RRT", "t", false, "child killed by signal 9")), 7);
}

}  // namespace ompl_log_test
}  // namespace parksim::bench
