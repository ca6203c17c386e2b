// --planner-command and --controller-command on the command line: the same planner and
// controller as `--planner command --planner-param command=...`, end to end through `parksim`.

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "tests/support/RunParksim.h"
#include "tests/support/TestPaths.h"

namespace parksim {
namespace {

using parksim::testing::runParksim;
using parksim::testing::sourceDir;

std::string outDir(const std::string& name) {
  const std::filesystem::path dir = parksim::testing::testOutputDir("command_cli/" + name);
  std::filesystem::remove_all(dir);
  return dir.string();
}

std::string headIn() { return sourceDir() + "/worlds/head_in.yaml"; }

TEST(CommandCliTest, RunsAPythonPlannerAndAPythonControllerUnderLab) {
  const std::string out = outDir("lab");
  const parksim::testing::CliRun run = runParksim(
      "run " + headIn() + " --realism lab --out " + out + " --planner-command 'python3 " +
      sourceDir() + "/examples/commands/waypoint_planner.py {problem} {out}' " +
      "--planner-param 'waypoints=0.1 0.5, 1.5 0.5' --controller-command 'python3 " + sourceDir() +
      "/examples/commands/tracking_controller.py'");
  EXPECT_EQ(run.exit_code, 0) << run.out;
  EXPECT_NE(run.out.find("(within tolerance)"), std::string::npos) << run.out;
  const std::string plan = parksim::testing::slurp(out + "/plan.json");
  EXPECT_NE(plan.find("\"planner\": \"command\""), std::string::npos);
  EXPECT_TRUE(std::filesystem::is_regular_file(out + "/executed.csv"));
}

TEST(CommandCliTest, APlannerThatHangsIsKilledAtItsLimit) {
  const std::string out = outDir("hang");
  const parksim::testing::CliRun run =
      runParksim("plan " + headIn() + " --out " + out +
                 " --planner-command \"sh -c 'sleep 60' sh {out}\" --planner-param timeout_s=0.2");
  EXPECT_EQ(run.exit_code, 6) << run.out;
  EXPECT_EQ(
      run.out,
      "parksim plan: planner_error: planner command `sh -c 'sleep 60' sh {out}` gave no answer "
      "within timeout_s = 0.2 s and was killed\n");
}

TEST(CommandCliTest, ACommandAndANameForOneComponentAreRefused) {
  const parksim::testing::CliRun planner =
      runParksim("plan " + headIn() + " --planner rrt --planner-command 'x {out}'");
  EXPECT_EQ(planner.exit_code, 2) << planner.out;
  EXPECT_NE(planner.out.find("excludes"), std::string::npos) << planner.out;
  const parksim::testing::CliRun controller =
      runParksim("run " + headIn() + " --controller tracking --controller-command x");
  EXPECT_EQ(controller.exit_code, 2) << controller.out;
  const parksim::testing::CliRun twice =
      runParksim("plan " + headIn() + " --planner-command 'true {out}' --planner-param command=y");
  EXPECT_EQ(twice.exit_code, 2) << twice.out;
  EXPECT_NE(twice.out.find("--planner-command and --planner-param command=... both give the "
                           "command"),
            std::string::npos)
      << twice.out;
}

}  // namespace
}  // namespace parksim
