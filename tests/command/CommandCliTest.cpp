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

// --planner-timeout and --controller-timeout hold for commands too: the program is stopped at the
// shorter of its own timeout and the run's limit, and the verdict names the limit that struck.
// Under `timeout 25`, so that a limit that does nothing fails here (exit 124) instead of
// waiting out the command's own 600 s (planner) or 30 s and 5 s (controller).
TEST(CommandCliTest, TheRunsTimeLimitsHoldForCommands) {
  const std::string bounded = "timeout 25 " + parksim::testing::parksimExe();
  const std::string faulty = "python3 " + sourceDir() + "/tests/command/faulty_controller.py";
  parksim::testing::CliRun run = parksim::testing::runProgram(
      bounded, "plan " + headIn() + " --out " + outDir("slow_plan") +
                   " --planner-command \"sh -c 'sleep 60' sh {out}\" --planner-timeout 1");
  EXPECT_EQ(run.exit_code, 6) << run.out;
  EXPECT_EQ(run.out,
            "parksim plan: planner_error: planner command `sh -c 'sleep 60' sh {out}` gave no "
            "answer within the planner time limit of 1 s and was killed\n");
  // The shorter limit strikes: the command's own here.
  run = parksim::testing::runProgram(
      bounded, "plan " + headIn() + " --out " + outDir("own_limit") +
                   " --planner-command \"sh -c 'sleep 60' sh {out}\" --planner-param "
                   "timeout_s=0.5 --planner-timeout 20");
  EXPECT_EQ(run.exit_code, 6) << run.out;
  EXPECT_NE(run.out.find("within timeout_s = 0.5 s and was killed"), std::string::npos) << run.out;
  for (const auto& [fault, message] :
       {std::pair<std::string, std::string>{
            "slowstart", "was not ready within the controller time limit of 1 s"},
        {"hang", "gave no answer at tick 5 within the controller time limit of 1 s"}}) {
    SCOPED_TRACE(fault);
    run = parksim::testing::runProgram(bounded, "run " + headIn() + " --out " + outDir(fault) +
                                                    " --controller-command '" + faulty + " " +
                                                    fault + "' --controller-timeout 1");
    EXPECT_EQ(run.exit_code, 6) << run.out;
    EXPECT_NE(run.out.find("parksim run: controller_error: controller command threw in "),
              std::string::npos)
        << run.out;
    EXPECT_NE(run.out.find(message), std::string::npos) << run.out;
  }
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
