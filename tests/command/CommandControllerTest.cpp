// The controller `command`: a process speaking parksim-controller/1, through the episode
// pipeline. A Python process with parksim's tracking law drives as the built-in controller
// does; processes that die, answer NaN or garbage, or never answer end their episode with
// controller_error, the record kept; every process ends with its episode.

#include "parksim/usercode/CommandController.h"

#include <signal.h>

#include <gtest/gtest.h>

#include <cerrno>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>

#include <nlohmann/json.hpp>

#include "parksim/core/io/AtomicFile.h"
#include "parksim/pipeline/EpisodePipeline.h"
#include "parksim/scenario/world/World.h"
#include "parksim/usercode/CommandLine.h"
#include "parksim/usercode/CommandPlanner.h"
#include "tests/support/TestPaths.h"

namespace parksim {
namespace {

namespace fs = std::filesystem;
using parksim::testing::sourceDir;

std::string script(const std::string& path) { return sourceDir() + "/" + path; }

// Head-in, planned by the example planner (a plan that needs no search: fast).
EpisodeRequest headInRun() {
  EpisodeRequest r;
  r.world = std::make_shared<const World>(loadWorld(sourceDir() + "/worlds/head_in.yaml"));
  r.plan.planner = kCommandPlanner;
  r.plan.planner_params = {
      {kCommandParam, quoteCommandLine({"python3", script("examples/commands/waypoint_planner.py"),
                                        "{problem}", "{out}"})},
      {"waypoints", "0.1 0.5, 1.5 0.5"}};
  return r;
}

EpisodeRequest withController(EpisodeRequest r, const std::vector<std::string>& command,
                              ParamMap params = {}) {
  r.controller = kCommandController;
  params[kCommandParam] = quoteCommandLine(command);
  r.controller_params = params;
  return r;
}

std::vector<std::string> trackingController() {
  return {"python3", script("examples/commands/tracking_controller.py")};
}

std::vector<std::string> faulty(const std::string& fault) {
  return {"python3", script("tests/command/faulty_controller.py"), fault};
}

fs::path testDir(const std::string& name) {
  const fs::path dir = parksim::testing::testOutputDir("command/" + name);
  fs::remove_all(dir);
  ensureDirectory(dir.string());
  return dir;
}

TEST(CommandControllerTest, TickLinesCarryEveryInputFieldInRoundTripText) {
  ControllerInput in;
  in.tick = 12;
  in.t_s = 0.05;
  in.pose = {0.1, 0.2, -1.5};
  in.encoders_rad = {3.0, -4.0};
  in.wheel_speeds_radps = {0.5, 0.25};
  in.reference = {std::nextafter(0.1, 1.0), 1.0 / 3.0, 2.0};
  in.reference_twist = {0.16, -0.5};
  in.feedforward = {7.5, 8.0};
  in.plan_ended = true;
  EXPECT_EQ(
      tickLine(in),
      "tick 12 0.05 0.1 0.2 -1.5 3 -4 0.5 0.25 0.10000000000000002 0.3333333333333333 2 0.16 -0.5 "
      "7.5 8 1\n");
  EXPECT_EQ(kTickFields.size(), 17u);
}

TEST(CommandControllerTest, AnswersAreTwoNumbers) {
  const auto w = parseWheelAnswer("  0.5\t-1e-3 \r");
  ASSERT_TRUE(w.has_value());
  EXPECT_EQ(w->left_radps, 0.5);
  EXPECT_EQ(w->right_radps, -1e-3);
  EXPECT_EQ(parseWheelAnswer("+2 3")->left_radps, 2.0);
  EXPECT_TRUE(std::isnan(parseWheelAnswer("nan 0")->left_radps));
  for (const char* bad : {"", "1", "1 2 3", "1,2", "a b", "1 2x", "0x1 2", "1  - 2"}) {
    EXPECT_FALSE(parseWheelAnswer(bad).has_value()) << bad;
  }
}

TEST(CommandControllerTest, APythonTrackingControllerDrivesAsTheBuiltInOne) {
  const EpisodeOutcome builtin = runEpisodePipeline(headInRun());
  const EpisodeOutcome python =
      runEpisodePipeline(withController(headInRun(), trackingController()));
  ASSERT_TRUE(python.verdict.met()) << python.verdict.reason;
  EXPECT_EQ(python.episode.metrics.controller, kCommandController);
  // The same law on the same inputs (round-trip text both ways): the same drive, up to the
  // last bits of the commands' arithmetic.
  ASSERT_EQ(python.episode.rows.size(), builtin.episode.rows.size());
  for (std::size_t i = 0; i < python.episode.rows.size(); i += 97) {
    EXPECT_NEAR(python.episode.rows[i].pose.x, builtin.episode.rows[i].pose.x, 1e-6) << i;
    EXPECT_NEAR(python.episode.rows[i].pose.y, builtin.episode.rows[i].pose.y, 1e-6) << i;
  }
  EXPECT_NEAR(python.episode.metrics.goal_pos_err_m, builtin.episode.metrics.goal_pos_err_m, 1e-6);
}

TEST(CommandControllerTest, UnderLabRealismItTracksWithinTolerance) {
  EpisodeRequest r = withController(headInRun(), trackingController());
  r.realism = "lab";
  const EpisodeOutcome out = runEpisodePipeline(r);
  EXPECT_TRUE(out.verdict.met()) << out.verdict.reason;
}

TEST(CommandControllerTest, TheResetMessageHoldsThePlanTheLoopAndTheParameters) {
  const fs::path dir = testDir("reset");
  const fs::path file = dir / "reset.json";
  // Keeps its reset line, then answers the feed-forward (tokens 15 and 16 of a tick line).
  const std::string program =
      "import sys\n"
      "open(sys.argv[1], 'w').write(sys.stdin.readline()[6:])\n"
      "print('ready', flush=True)\n"
      "for line in sys.stdin:\n"
      "    print(*line.split()[15:17], flush=True)\n";
  EpisodeRequest r =
      withController(headInRun(), {"python3", "-c", program, file.string()}, {{"gain", "3"}});
  const EpisodeOutcome out = runEpisodePipeline(r);
  ASSERT_TRUE(out.episode.metrics.controller_error.empty()) << out.episode.metrics.controller_error;
  std::ifstream in(file);
  const nlohmann::json reset = nlohmann::json::parse(in);
  EXPECT_EQ(reset["format"], kControllerProtocol);
  EXPECT_EQ(reset["period_s"], 1.0 / 240.0);  // the ideal robot: every physics step
  EXPECT_EQ(reset["latency_s"], 0.0);
  EXPECT_EQ(reset["estimated_pose"], false);
  EXPECT_EQ(reset["params"], nlohmann::json({{"gain", "3"}}));
  EXPECT_EQ(reset["tick_fields"].size(), kTickFields.size());
  EXPECT_EQ(reset["world"]["name"], "head_in");
  const nlohmann::json& rows = reset["plan"]["rows"];
  ASSERT_EQ(rows.size(), out.trajectory.points.size());
  const TrajectoryPoint& p = out.trajectory.points[100];
  EXPECT_EQ(rows[100], nlohmann::json({p.t_s, p.pose.x, p.pose.y, p.pose.theta, p.wheels.left_radps,
                                       p.wheels.right_radps}));
}

struct Fault {
  std::string fault;
  std::string reason;  // the verdict's reason after "controller command "
};

void PrintTo(const Fault& f, std::ostream* os) { *os << f.fault; }

class CommandControllerFaultTest : public ::testing::TestWithParam<Fault> {};

TEST_P(CommandControllerFaultTest, EndsTheEpisodeWithControllerErrorKeepingTheRecord) {
  const Fault& f = GetParam();
  const std::string shown = quoteCommandLine(faulty(f.fault));
  // Short time limits only where they are what fails: a loaded machine may take a second to
  // start Python.
  ParamMap limits;
  if (f.fault == "hang") limits["tick_timeout_s"] = "0.3";
  if (f.fault == "slowstart") limits["start_timeout_s"] = "0.3";
  const EpisodeOutcome out =
      runEpisodePipeline(withController(headInRun(), faulty(f.fault), limits));
  EXPECT_EQ(out.verdict.status, EpisodeStatus::kControllerError);
  std::string expected = "controller command " + f.reason;
  const std::size_t at = expected.find("$P");
  if (at != std::string::npos) expected.replace(at, 2, shown);
  EXPECT_EQ(out.verdict.reason, expected);
  // The record up to the failure is kept: the first row and the one where it failed.
  ASSERT_FALSE(out.episode.rows.empty());
  EXPECT_EQ(out.episode.rows.front().t_s, 0.0);
}

// The faulty process answers ticks 0 to 4 and fails at tick 5, t = 5/240 s.
INSTANTIATE_TEST_SUITE_P(
    Faults, CommandControllerFaultTest,
    ::testing::Values(
        Fault{"exit",
              "threw in command at t = 0.021 s: process `$P` exited with status 3 at tick 5 "
              "(stderr: controller gave up at tick 5)"},
        Fault{"nan", "returned (nan, nan) rad/s at t = 0.021 s: not a number"},
        Fault{"range",
              "returned (1e+06, 0) rad/s at t = 0.021 s: beyond robot.max_wheel_speed_radps 10"},
        Fault{"garbage",
              "threw in command at t = 0.021 s: process `$P` answered 'left is fast' at tick 5: "
              "expected 'LEFT RIGHT', two numbers in rad/s"},
        Fault{"long",
              "threw in command at t = 0.021 s: process `$P` answered at tick 5 with a line "
              "longer than 1024 bytes"},
        Fault{"hang",
              "threw in command at t = 0.021 s: process `$P` gave no answer at tick 5 within "
              "tick_timeout_s = 0.3 s"},
        Fault{"close",
              "threw in command at t = 0.021 s: process `$P` closed its standard input or "
              "output at tick 5"},
        Fault{"notready",
              "threw in reset at t = 0.000 s: process `$P` answered 'hello' to reset, not "
              "'ready'"},
        Fault{"slowstart",
              "threw in reset at t = 0.000 s: process `$P` was not ready within "
              "start_timeout_s = 0.3 s"}),
    [](const ::testing::TestParamInfo<Fault>& info) { return info.param.fault; });

TEST(CommandControllerTest, EachEpisodeStartsItsOwnProcessAndEndsIt) {
  const fs::path pids = testDir("lifetime") / "pids.txt";
  // The shell records its pid, then becomes the controller (exec: the same process).
  std::vector<std::string> command = {"sh", "-c", "echo $$ >> " + pids.string() + "; exec \"$@\"",
                                      "sh"};
  for (const std::string& w : trackingController()) command.push_back(w);
  EpisodeRequest r = withController(headInRun(), command);
  r.realisations = 2;
  r.realism = "lab";
  const EpisodeOutcome out = runEpisodePipeline(r);
  EXPECT_TRUE(out.verdict.met()) << out.verdict.reason;
  std::ifstream in(pids);
  std::set<pid_t> seen;
  for (pid_t pid = 0; in >> pid;) seen.insert(pid);
  EXPECT_EQ(seen.size(), 2u);  // one process per realisation
  for (const pid_t pid : seen) {
    // Ended and reaped: no such process, not even a zombie.
    EXPECT_EQ(::kill(pid, 0), -1) << pid;
    EXPECT_EQ(errno, ESRCH) << pid;
  }
}

}  // namespace
}  // namespace parksim
