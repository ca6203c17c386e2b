// Benchmark statistics: unsolved runs count as infinitely slow, medians over solved paths,
// the study's figures, and the issue-5 verdicts.

#include "bench/planning/BenchSummary.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace parksim::bench {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

BenchRecord run(const std::string& library, const std::string& planner, const std::string& space,
                const std::string& budget, bool solved, double t_first, double length) {
  BenchRecord r;
  r.library = library;
  r.planner = planner;
  r.space = space;
  r.scenario = "head_in";
  r.budget = budget;
  r.solved = solved;
  r.valid = solved;
  r.time_first_s = solved ? t_first : kNotMeasured;
  r.time_total_s = t_first;
  r.length_m = solved ? length : kNotMeasured;
  r.cusps = solved ? 1 : -1;
  return r;
}

TEST(BenchSummary, QuantileInterpolatesAndKeepsUnsolvedRunsLast) {
  EXPECT_DOUBLE_EQ(quantile({3.0, 1.0, 2.0}, 0.5), 2.0);
  EXPECT_DOUBLE_EQ(quantile({1.0, 2.0, 3.0, 4.0}, 0.5), 2.5);
  EXPECT_DOUBLE_EQ(quantile({1.0, 2.0, kInf}, 0.5), 2.0);
  EXPECT_TRUE(std::isinf(quantile({1.0, 2.0, kInf}, 0.9)));
  EXPECT_TRUE(std::isinf(quantile({1.0, kInf}, 0.5)));
  EXPECT_TRUE(std::isnan(quantile({}, 0.5)));
}

TEST(BenchSummary, GroupsCountSuccessAndTakeMediansOverSolvedPaths) {
  const std::vector<BenchRecord> records = {
      run("parksim", "rrt", "move-to-pose", "iterations=2000", true, 0.001, 2.0),
      run("parksim", "rrt", "move-to-pose", "iterations=2000", true, 0.003, 4.0),
      run("parksim", "rrt", "move-to-pose", "iterations=2000", false, 0.010, 0.0),
      run("ompl", "RRT", "reeds-shepp", "time=1s", true, 0.002, 1.0),
  };
  const std::vector<GroupSummary> groups = summarize(records);
  ASSERT_EQ(groups.size(), 2u);
  const GroupSummary& g = groups[0];
  EXPECT_EQ(g.runs, 3);
  EXPECT_EQ(g.solved, 2);
  EXPECT_EQ(g.valid, 2);
  EXPECT_DOUBLE_EQ(g.time_first_median_s, 0.003);
  EXPECT_TRUE(std::isinf(g.time_first_p90_s));
  EXPECT_DOUBLE_EQ(g.length_median_m, 3.0);
  EXPECT_DOUBLE_EQ(g.cusps_median, 1.0);
  EXPECT_EQ(groups[1].library, "ompl");
}

TEST(BenchSummary, StudyFiguresAreThePythonTimings) {
  EXPECT_EQ(studyPlanningTime("head_in", "rrt-goal-connect"), 40.0);
  EXPECT_EQ(studyPlanningTime("parallel", "rrt-goal-connect"), 101.6);
  EXPECT_EQ(studyPlanningTime("head_in", "rrt"), 27.5);
  EXPECT_FALSE(studyPlanningTime("parallel", "rrt").has_value());
}

TEST(BenchSummary, ComparisonNamesTheFastestPlannersAndTheVerdict) {
  std::vector<BenchRecord> records;
  for (int i = 0; i < 4; ++i) {
    records.push_back(run("parksim", "rrt", "move-to-pose", "iterations=2000", true, 0.004, 2.0));
    records.push_back(
        run("parksim", "rrt-goal-connect", "move-to-pose", "iterations=2000", true, 0.002, 2.0));
    // Smoothing starts after the first solution: a smoothed variant never counts as faster.
    records.push_back(
        run("parksim", "rrt+smooth", "move-to-pose", "iterations=2000", true, 0.0001, 1.0));
    records.push_back(run("ompl", "RRTConnect", "reeds-shepp", "time=1s", true, 0.001, 3.0));
    records.push_back(run("ompl", "RRTConnect", "se2", "time=1s", true, 0.0001, 1.0));
    records.push_back(run("ompl", "RRTstar", "reeds-shepp", "time=1s", true, 0.003, 1.5));
    records.push_back(run("parksim", "rrt-star", "move-to-pose", "time=0.1s", true, 0.003, 1.4));
  }
  const std::string table = formatComparison(summarize(records));
  // Fastest parksim planner (goal-connect, 2 ms) vs fastest Reeds-Shepp planner (1 ms): behind.
  EXPECT_NE(table.find("parksim rrt-goal-connect (move-to-pose, iterations=2000): 2.000 ms"),
            std::string::npos)
      << table;
  EXPECT_NE(table.find("ompl RRTConnect (reeds-shepp, time=1s): 1.000 ms"), std::string::npos);
  EXPECT_NE(table.find("| 2 "), std::string::npos);
  EXPECT_NE(table.find("| NO "), std::string::npos);
  // The anytime run's 1.4 m beats RRTstar's 1.5 m.
  EXPECT_NE(table.find("| 0.933 "), std::string::npos);
  EXPECT_NE(table.find("| yes "), std::string::npos);
}

TEST(BenchSummary, ComparisonShowsTheBestOfEachSteeringFunctionToo) {
  std::vector<BenchRecord> records;
  for (int i = 0; i < 3; ++i) {
    records.push_back(run("parksim", "rrt", "move-to-pose", "iterations=2000", true, 0.004, 2.0));
    records.push_back(
        run("parksim", "rrt", "rotate-translate-rotate", "iterations=2000", true, 0.0002, 2.0));
    records.push_back(run("ompl", "RRTConnect", "reeds-shepp", "time=1s", true, 0.001, 3.0));
  }
  const std::string table = formatComparison(summarize(records));
  EXPECT_NE(table.find("| time to first solution, median "), std::string::npos) << table;
  EXPECT_NE(table.find("| same, best move-to-pose planner "), std::string::npos);
  EXPECT_NE(table.find("| same, best rotate-translate-rotate planner "), std::string::npos);
  EXPECT_NE(table.find("| 4 "), std::string::npos);    // move-to-pose: 4 ms vs 1 ms, behind
  EXPECT_NE(table.find("| 0.2 "), std::string::npos);  // rotate-translate-rotate: ahead
}

}  // namespace
}  // namespace parksim::bench
