// The planning benchmark program end to end (bench/parksim_bench.cpp).

#include <algorithm>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "tests/support/RunParksim.h"
#include "tests/support/TestPaths.h"

namespace parksim {
namespace {

namespace fs = std::filesystem;
using testing::CliRun;
using testing::slurp;

// Runs `parksim-bench ARGS` (beside the other benchmark programs in the build tree).
CliRun runBench(const std::string& args) {
  return testing::runProgram(testing::binaryDir() + "/bench/parksim-bench", args);
}

TEST(ParksimBench, WritesTheCsvWithItsRequiredColumns) {
  const fs::path out = testing::testOutputDir("parksim_bench");
  fs::remove_all(out);
  const CliRun r = runBench(testing::sourceDir() + "/worlds/head_in.yaml" +
                            " --seeds 2 --planners rrt-goal-connect,time-a-star"
                            " --steering reeds-shepp,balkcom-mason --ompl"
                            " --ompl-planners RRTConnect --ompl-spaces reeds-shepp --out " +
                            out.string());
  ASSERT_EQ(r.exit_code, 0) << r.out;
  const std::string csv = slurp(out / "bench.csv");
  const std::string header = csv.substr(0, csv.find('\n'));
  for (const char* column : {"library", "planner", "scenario", "seed", "solved", "time_first_s",
                             "length_m", "cusps", "min_clearance_m"}) {
    EXPECT_NE(header.find(column), std::string::npos) << column;
  }
  // 2 seeds x (1 tree planner x 2 steering functions + time-a-star, which has its own moves
  // and runs once, + 1 OMPL planner) rows.
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 1 + 2 * (2 + 1 + 1)) << csv;
  EXPECT_NE(csv.find(",time-a-star,primitives+balkcom-mason,"), std::string::npos) << csv;
  EXPECT_NE(csv.find("\nompl,"), std::string::npos);
  EXPECT_NE(csv.find("\nparksim,"), std::string::npos);
  const std::string summary = slurp(out / "summary.md");
  EXPECT_NE(summary.find("## parksim vs OMPL\n"), std::string::npos) << summary;
  EXPECT_EQ(summary.find("issue"), std::string::npos) << summary;  // speaks to users
}

// Without --planners, every planner that runs with its defaults: all of parksim's but the
// command planner, whose command line no bench option gives (the README's first bench command).
TEST(ParksimBench, WithoutPlannersEveryPlannerThatRunsWithItsDefaults) {
  const fs::path out = testing::testOutputDir("parksim_bench_all");
  fs::remove_all(out);
  const CliRun r = runBench(testing::sourceDir() + "/worlds/head_in.yaml" +
                            " --seeds 1 --steering balkcom-mason --out " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.out;
  const std::string csv = slurp(out / "bench.csv");
  for (const char* planner : {",time-a-star,", ",hybrid-a-star,", ",rrt,", ",rrt-connect,",
                              ",rrt-goal-connect,", ",rrt-star,"}) {
    EXPECT_NE(csv.find(planner), std::string::npos) << planner << "\n" << csv;
  }
  EXPECT_EQ(csv.find(",command,"), std::string::npos) << csv;
}

// A plugin's planner is benchmarked beside the built-ins, its paths checked like theirs.
TEST(ParksimBench, APluginsPlannerRunsBesideTheBuiltIns) {
  const fs::path out = testing::testOutputDir("parksim_bench_plugin");
  fs::remove_all(out);
  const CliRun r = runBench(testing::sourceDir() + "/worlds/head_in.yaml --seeds 2 --plugin " +
                            testing::binaryDir() +
                            "/examples/plugins/libparksim_example_plugins.so"
                            " --planners example,time-a-star --steering balkcom-mason --out " +
                            out.string());
  ASSERT_EQ(r.exit_code, 0) << r.out;
  const std::string csv = slurp(out / "bench.csv");
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 1 + 2 * 2) << csv;
  EXPECT_NE(csv.find("\nparksim,example,balkcom-mason,"), std::string::npos) << csv;
  EXPECT_NE(slurp(out / "summary.md").find("Every solved path passed"), std::string::npos);
  // Without the plugin the name is unknown.
  EXPECT_EQ(runBench(testing::sourceDir() + "/worlds/head_in.yaml --planners example").exit_code,
            2);
}

TEST(ParksimBench, BadInputIsOneLineAndExitTwo) {
  const CliRun r = runBench(testing::sourceDir() + "/worlds/head_in.yaml --seeds 0");
  EXPECT_EQ(r.exit_code, 2) << r.out;
  EXPECT_NE(r.out.find("parksim-bench: error:"), std::string::npos) << r.out;
  const CliRun budget =
      runBench(testing::sourceDir() + "/worlds/head_in.yaml --max-iterations 0 --out " +
               testing::testOutputDir("parksim_bench_zero").string());
  EXPECT_EQ(budget.exit_code, 2) << budget.out;
  EXPECT_NE(budget.out.find("--max-iterations: expected auto or an integer in [1, 1000000]"),
            std::string::npos)
      << budget.out;
}

}  // namespace
}  // namespace parksim
