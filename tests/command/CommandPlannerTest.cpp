// The planner `command`: a program run as a command, through the episode pipeline as every
// front-end runs it. A Python planner solves the study's head-in world; commands that fail,
// write garbage, hang or plan through a wall get their own verdicts, naming the command.

#include "parksim/usercode/CommandPlanner.h"

#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include <nlohmann/json.hpp>

#include "parksim/core/io/AtomicFile.h"
#include "parksim/core/io/Error.h"
#include "parksim/pipeline/EpisodePipeline.h"
#include "parksim/pipeline/EpisodeSettings.h"
#include "parksim/scenario/world/World.h"
#include "parksim/usercode/CommandLine.h"
#include "parksim/usercode/ProblemFile.h"
#include "tests/support/TestPaths.h"

namespace parksim {
// Named, not anonymous: its program is compiled as one unity batch, where another file's
// helpers of the same names would meet these.
namespace command_planner_test {

namespace fs = std::filesystem;
using parksim::testing::sourceDir;

std::shared_ptr<const World> headIn() {
  return std::make_shared<const World>(loadWorld(sourceDir() + "/worlds/head_in.yaml"));
}

// The example planner (examples/commands/waypoint_planner.py) as a command line.
std::string waypointPlanner() {
  return quoteCommandLine(
      {"python3", sourceDir() + "/examples/commands/waypoint_planner.py", "{problem}", "{out}"});
}

// The waypoints that take the head-in robot through the wall's gap, above the parked row.
constexpr const char* kHeadInWaypoints = "0.1 0.5, 1.5 0.5";

EpisodeRequest planWith(const std::string& command, const ParamMap& params = {}) {
  EpisodeRequest r;
  r.world = headIn();
  r.plan.planner = kCommandPlanner;
  r.plan.planner_params = params;
  r.plan.planner_params[kCommandParam] = command;
  r.drive = false;
  return r;
}

fs::path testDir(const std::string& name) {
  const fs::path dir = parksim::testing::testOutputDir("command/" + name);
  fs::remove_all(dir);
  ensureDirectory(dir.string());
  return dir;
}

TEST(CommandPlannerTest, IsRegisteredAsUserCodeNeverTrusted) {
  const Components components;
  const PlannerInfo& info = components.planners.find(kCommandPlanner).info;
  EXPECT_TRUE(info.runs_user_code);
  EXPECT_FALSE(info.trusted);
  EXPECT_EQ(info.plugin, "");
  ASSERT_EQ(info.params.size(), 2u);
  EXPECT_EQ(info.params[0].name, "command");
  EXPECT_EQ(info.params[1].name, "timeout_s");
  EXPECT_EQ(info.params[1].default_text, "600");
}

TEST(CommandPlannerTest, APythonPlannerSolvesHeadInAndItsPlanIsDriven) {
  EpisodeRequest r = planWith(waypointPlanner(), {{"waypoints", kHeadInWaypoints}});
  r.drive = true;
  const EpisodeOutcome out = runEpisodePipeline(r);
  ASSERT_TRUE(out.verdict.met()) << out.verdict.reason;
  ASSERT_TRUE(out.plan && out.plan->solved());
  const Scenario& s = r.world->scenario;
  // The plan is the exact integral of its wheel speeds from the start to the goal.
  const Pose2& first = out.trajectory.points.front().pose;
  const Pose2& last = out.trajectory.points.back().pose;
  EXPECT_EQ(first.x, s.start.x);
  EXPECT_EQ(first.y, s.start.y);
  EXPECT_NEAR(last.x, s.goal.pose.x, 1e-9);
  EXPECT_NEAR(last.y, s.goal.pose.y, 1e-9);
  EXPECT_NEAR(std::remainder(last.theta - s.goal.pose.theta, 2 * M_PI), 0.0, 1e-9);
  // Path: 0.4 m north, 1.4 m east, 0.46 m south.
  EXPECT_NEAR(out.trajectory.pathLength(s.robot), 0.4 + 1.4 + 0.46, 1e-9);
  EXPECT_EQ(out.episode.metrics.contacts, 0);
  EXPECT_EQ(out.plan_summary.value("planner", ""), kCommandPlanner);
}

TEST(CommandPlannerTest, ACollidingPlanIsPlanInvalidNamingTheObstacleAndIsNotDriven) {
  // Without waypoints the example drives straight at the goal, through wall_2.
  EpisodeRequest r = planWith(waypointPlanner());
  r.drive = true;
  const EpisodeOutcome out = runEpisodePipeline(r);
  EXPECT_EQ(out.verdict.status, EpisodeStatus::kPlanInvalid);
  EXPECT_NE(out.verdict.reason.find("the footprint overlaps wall_2"), std::string::npos)
      << out.verdict.reason;
  EXPECT_FALSE(out.driven());
}

TEST(CommandPlannerTest, ANonZeroExitIsPlannerErrorNamingTheCommandAndItsStderr) {
  const std::string command = "sh -c 'echo starting; echo no licence >&2; exit 1' sh {out}";
  const EpisodeOutcome out = runEpisodePipeline(planWith(command));
  EXPECT_EQ(out.verdict.status, EpisodeStatus::kPlannerError);
  EXPECT_EQ(out.verdict.reason,
            "planner command `" + command + "` exited with status 1 (stderr: no licence)");
}

TEST(CommandPlannerTest, AMalformedAnswerIsPlannerError) {
  const EpisodeOutcome out =
      runEpisodePipeline(planWith("sh -c 'echo garbage > \"$1/trajectory.csv\"' sh {out}"));
  EXPECT_EQ(out.verdict.status, EpisodeStatus::kPlannerError);
  EXPECT_NE(out.verdict.reason.find("wrote a bad plan: {out}/trajectory.csv:1: header lacks "
                                    "column 't'"),
            std::string::npos)
      << out.verdict.reason;
}

TEST(CommandPlannerTest, NoAnswerFileIsPlannerError) {
  const EpisodeOutcome out = runEpisodePipeline(planWith("sh -c true sh {out}"));
  EXPECT_EQ(out.verdict.status, EpisodeStatus::kPlannerError);
  EXPECT_EQ(out.verdict.reason,
            "planner command `sh -c true sh {out}` exited with status 0 but wrote no "
            "{out}/trajectory.csv");
}

TEST(CommandPlannerTest, AHeaderWithoutRowsIsNoPlan) {
  const EpisodeOutcome out = runEpisodePipeline(
      planWith("sh -c 'echo t,x,y,theta,omega_left,omega_right > \"$1/trajectory.csv\"; echo "
               "no way through >&2' sh {out}"));
  EXPECT_EQ(out.verdict.status, EpisodeStatus::kPlanFailed);
  ASSERT_TRUE(out.plan.has_value());
  EXPECT_EQ(out.plan->message, "the command found no plan: no way through");
}

TEST(CommandPlannerTest, ACommandThatHangsIsKilledWithEverythingItStarted) {
  // Orphans come to this process, so that it can see how they ended.
  ASSERT_EQ(::prctl(PR_SET_CHILD_SUBREAPER, 1), 0);
  const fs::path pid_file = testDir("hang") / "sleeper.pid";
  const EpisodeOutcome out = runEpisodePipeline(
      planWith("sh -c 'sleep 60 & echo $! > " + pid_file.string() + "; wait' sh {out}",
               {{"timeout_s", "0.3"}}));
  EXPECT_EQ(out.verdict.status, EpisodeStatus::kPlannerError);
  EXPECT_NE(out.verdict.reason.find("gave no answer within timeout_s = 0.3 s and was killed"),
            std::string::npos)
      << out.verdict.reason;
  std::ifstream in(pid_file);
  pid_t sleeper = 0;
  ASSERT_TRUE(in >> sleeper);
  int status = 0;
  ASSERT_EQ(::waitpid(sleeper, &status, 0), sleeper);
  EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGKILL) << status;
}

TEST(CommandPlannerTest, TheProblemFileHoldsTheWorldTheBudgetAndTheOtherParameters) {
  const fs::path dir = testDir("problem");
  EpisodeRequest r =
      planWith("sh -c 'cp \"$1\" " + (dir / "problem.json").string() + "; echo \"$2\" > " +
                   (dir / "out.txt").string() +
                   "; echo t,x,y,theta,omega_left,omega_right > \"$2/trajectory.csv\"' "
                   "sh {problem} {out}",
               {{"timeout_s", "30"}, {"note", "hello world"}});
  r.plan.search.seed = 7;
  const EpisodeOutcome out = runEpisodePipeline(r);
  EXPECT_EQ(out.verdict.status, EpisodeStatus::kPlanFailed);
  std::ifstream file(dir / "problem.json");
  const nlohmann::json p = nlohmann::json::parse(file);
  EXPECT_EQ(p["format"], "parksim-planning-problem/1");
  // Only what the command planner does not read itself.
  EXPECT_EQ(p["params"], nlohmann::json({{"note", "hello world"}}));
  EXPECT_EQ(p["budget"]["seed"], 7);
  EXPECT_EQ(p["budget"]["max_iterations"], 2000);  // the study lot's automatic budget
  // 20 % of the 10 rad/s wheel limit is left to feedback (PlanSetup::feedback_headroom).
  EXPECT_EQ(p["timing"]["max_wheel_speed_radps"], 8.0);
  EXPECT_EQ(p["timing"]["period_s"], 0.02);
  const Scenario& s = r.world->scenario;
  EXPECT_EQ(p["world"], worldJson(s));
  const nlohmann::json& w = p["world"];
  EXPECT_EQ(w["start"]["x_m"], 0.1);
  EXPECT_EQ(w["goal"]["position_tolerance_m"], 0.001);
  ASSERT_EQ(w["obstacles"].size(), s.obstacles.size());
  EXPECT_EQ(w["obstacles"][1]["name"], "wall_2");
  EXPECT_EQ(w["obstacles"][1]["shape"], "box");
  EXPECT_EQ(w["obstacles"][1]["center_m"], nlohmann::json({0.55, 0.2}));
  EXPECT_EQ(w["obstacles"][1]["size_m"], nlohmann::json({0.1, 0.4}));
  EXPECT_EQ(w["robot"]["wheel_base_m"], 0.085);
  // The private directory the command wrote into is gone.
  std::ifstream out_txt(dir / "out.txt");
  std::string out_dir;
  ASSERT_TRUE(std::getline(out_txt, out_dir));
  EXPECT_TRUE(fs::path(out_dir).is_absolute());
  EXPECT_FALSE(fs::exists(fs::path(out_dir).parent_path())) << out_dir;
}

TEST(CommandPlannerTest, BadParametersAreInputErrorsBeforeAnythingRuns) {
  EXPECT_THROW(runEpisodePipeline(planWith("sh -c true {out}", {{"timeout_s", "-1"}})), Error);
  EXPECT_THROW(runEpisodePipeline(planWith("sh -c true")), Error);
}

}  // namespace command_planner_test
}  // namespace parksim
