// End-to-end tests of the parksim executable: exit codes, files written, messages.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tests/support/RunParksim.h"

#include "parksim/core/model/DiffDrive.h"
#include "parksim/core/model/Geometry.h"
#include "parksim/core/model/Trajectory.h"
#include "parksim/core/system/Provenance.h"
#include "parksim/planner/base/PlanScenario.h"
#include "parksim/renders/image/PngEncoder.h"
#include "parksim/renders/plots/FigureSelection.h"
#include "parksim/results/episode/TrajectoryFile.h"
#include "parksim/scenario/world/ScenarioReader.h"
#include "tests/support/TestPaths.h"

namespace parksim {
namespace {

namespace fs = std::filesystem;

using testing::CliRun;
using testing::slurp;

CliRun parksim(const std::string& args) { return testing::runParksim(args); }

class Cli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = parksim::testing::testOutputDir(
        "cli_" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string world(const std::string& name) {
    return parksim::testing::sourceDir() + "/worlds/" + name;
  }
  fs::path dir_;
};

TEST_F(Cli, PlanWritesAConsistentTrajectoryAndSummary) {
  for (const char* name : {"head_in.yaml", "parallel.yaml"}) {
    const fs::path out = dir_ / name;
    const CliRun r = parksim("plan " + world(name) + " --seed 3 --out " + out.string());
    ASSERT_EQ(r.exit_code, 0) << r.out;
    const Scenario s = loadScenario(world(name));
    const Trajectory t = readTrajectoryCsv((out / "trajectory.csv").string());
    // Each row's wheel speeds, held for the period and integrated exactly, reach the next row.
    for (std::size_t i = 0; i + 1 < t.points.size(); ++i) {
      const Pose2 next = integrateExact(t.points[i].pose, toTwist(t.points[i].wheels, s.robot),
                                        t.points[i + 1].t_s - t.points[i].t_s);
      EXPECT_LT(positionDistance(next, t.points[i + 1].pose), 1e-4);
      EXPECT_NEAR(t.points[i + 1].t_s - t.points[i].t_s, PlanSetup{}.timing_period_s, 1e-9);
    }
    const auto plan = nlohmann::json::parse(slurp(out / "plan.json"));
    EXPECT_EQ(plan["status"], "solved");
    EXPECT_EQ(plan["seed"], 3);
    EXPECT_EQ(plan["planner"], "time-a-star");  // the default since issue 18
    EXPECT_LE(plan["final_pos_err_m"].get<double>(), 0.001);
    EXPECT_LE(plan["final_heading_err_deg"].get<double>(), 0.5);
    EXPECT_NEAR(plan["path_length_m"].get<double>(), t.pathLength(s.robot), 1e-9);
    for (const char* key : {"iterations", "tree_size", "planning_time_s", "phase_times_s"}) {
      EXPECT_TRUE(plan.contains(key)) << key;
    }
  }
}

TEST_F(Cli, SameSeedGivesByteIdenticalTrajectoryFiles) {
  for (const char* planner : {"rrt", "rrt-goal-connect"}) {
    const std::string common =
        "plan " + world("parallel.yaml") + " --seed 7 --planner " + planner + " --out ";
    ASSERT_EQ(parksim(common + (dir_ / "a").string()).exit_code, 0);
    ASSERT_EQ(parksim(common + (dir_ / "b").string()).exit_code, 0);
    EXPECT_EQ(slurp(dir_ / "a" / "trajectory.csv"), slurp(dir_ / "b" / "trajectory.csv"));
  }
}

TEST_F(Cli, UnsolvedPlanExitsNonZeroAndWritesNoTrajectory) {
  const fs::path out = dir_ / "out";
  const CliRun r = parksim("plan " + world("head_in.yaml") +
                           " --max-iterations 1 --planner rrt --out " + out.string());
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.out.find("unsolved plan (iteration_limit)"), std::string::npos) << r.out;
  EXPECT_FALSE(fs::exists(out / "trajectory.csv"));
  EXPECT_EQ(nlohmann::json::parse(slurp(out / "plan.json"))["status"], "iteration_limit");
}

TEST_F(Cli, MalformedWorldIsRefusedWithOneLineAndNoOutput) {
  const fs::path bad = dir_ / "bad.yaml";
  std::string text = slurp(world("head_in.yaml"));
  const std::size_t at = text.find("\nstart: [");
  ASSERT_NE(at, std::string::npos);
  text.insert(at + 1, "bogus_key: 1\n");
  std::ofstream(bad) << text;
  const fs::path out = dir_ / "never";
  const CliRun r = parksim("plan " + bad.string() + " --out " + out.string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 1) << r.out;
  EXPECT_NE(r.out.find(bad.string() + ":"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("bogus_key"), std::string::npos) << r.out;
  EXPECT_FALSE(fs::exists(out));
}

// Regression (issue 39): a ROS map YAML key nav2's map_server ignores (a `centerline`) was
// refused. It is ignored as map_server ignores it, with one warning line naming the file, line
// and key, by plan and import alike.
TEST_F(Cli, AMapKeyMapServerIgnoresIsWarnedAboutNotRefused) {
  fs::create_directories(dir_ / "maps");
  const std::string src = parksim::testing::sourceDir() + "/worlds/";
  fs::copy_file(src + "ros_lab.yaml", dir_ / "ros_lab.yaml");
  fs::copy_file(src + "maps/lab.pgm", dir_ / "maps" / "lab.pgm");
  std::ofstream(dir_ / "maps" / "lab.yaml")
      << slurp(src + "maps/lab.yaml") << "centerline: [[0, 0], [1, 0]]\n";
  const int line = 8;  // lab.yaml's seven lines, then the key
  const std::string warning = "warning: " + (dir_ / "maps" / "lab.yaml").string() + ":" +
                              std::to_string(line) +
                              ": centerline: not a key nav2's map_server reads";
  const CliRun plan =
      parksim("plan " + (dir_ / "ros_lab.yaml").string() + " -q --out " + (dir_ / "out").string());
  EXPECT_EQ(plan.exit_code, 0) << plan.out;
  EXPECT_EQ(plan.out.rfind(warning, 0), 0u) << plan.out;
  EXPECT_EQ(std::count(plan.out.begin(), plan.out.end(), '\n'), 1) << plan.out;
  const CliRun import = parksim("import " + (dir_ / "maps" / "lab.yaml").string() + " --out " +
                                (dir_ / "imported.yaml").string());
  EXPECT_EQ(import.exit_code, 0) << import.out;
  EXPECT_NE(import.out.find(warning), std::string::npos) << import.out;
}

TEST_F(Cli, MissingWorldFileAndBadOptionsAreRefused) {
  const fs::path out = dir_ / "never";
  CliRun r = parksim("plan " + (dir_ / "missing.yaml").string() + " --out " + out.string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.out.find("missing.yaml"), std::string::npos) << r.out;
  r = parksim("plan " + world("head_in.yaml") + " --planner nope --out " + out.string());
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.out.find("unknown planner 'nope'"), std::string::npos) << r.out;
  EXPECT_FALSE(fs::exists(out));
}

TEST_F(Cli, BenchIsItsOwnProgramAndTheMessageSaysSo) {
  const CliRun r = parksim("bench " + world("head_in.yaml"));
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.out.find("the planning benchmark is the program parksim-bench"), std::string::npos)
      << r.out;
}

TEST_F(Cli, RunWithFramesFilmsTheEpisodeAndDrawsTheFigures) {
  const fs::path out = dir_ / "film";
  const CliRun r = parksim("run " + world("head_in.yaml") +
                           " --frames --fps 2 --size 160x120 --out " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.out;
  const auto m = nlohmann::json::parse(slurp(out / "metrics.json"));
  const double sim_time = m["sim_time_s"].get<double>();
  int frames = 0;
  for (const auto& e : fs::directory_iterator(out / "frames")) {
    EXPECT_EQ(e.path().extension(), ".png");
    ++frames;
  }
  // One frame every 0.5 s of simulated time from t = 0, and one for the last sample.
  EXPECT_GE(frames, static_cast<int>(sim_time * 2));
  EXPECT_LE(frames, static_cast<int>(sim_time * 2) + 2);
  int figures = 0;
  for (const auto& e : fs::directory_iterator(out / "figures")) {
    EXPECT_EQ(e.path().extension(), ".png");
    EXPECT_GT(fs::file_size(e.path()), 1000u) << e.path();
    ++figures;
  }
  EXPECT_EQ(figures, static_cast<int>(kFigureNames.size()));  // --frames alone: all of them
  EXPECT_TRUE(fs::exists(out / "figures" / "tracking_error.png"));
  EXPECT_TRUE(fs::exists(out / "figures" / "plan_time-a-star.png"));  // the default planner
}

TEST_F(Cli, PngCompressionChangesTheFilesNotThePixels) {
  const std::string args = " --frames --figures none --fps 1 --size 160x120 --seed 1";
  const fs::path a = dir_ / "default";
  const fs::path b = dir_ / "stored";
  ASSERT_EQ(parksim("run " + world("head_in.yaml") + args + " --out " + a.string()).exit_code, 0);
  ASSERT_EQ(parksim("run " + world("head_in.yaml") + args + " --png-compression stored --out " +
                    b.string())
                .exit_code,
            0);
  const fs::path first = fs::path("frames") / "000000.png";
  EXPECT_GT(fs::file_size(b / first), fs::file_size(a / first));  // 3 bytes a pixel
  const RgbImage pa = readPng((a / first).string());
  const RgbImage pb = readPng((b / first).string());
  EXPECT_EQ(pa.width, pb.width);
  EXPECT_EQ(pa.pixels, pb.pixels);
  EXPECT_EQ(parksim("run " + world("head_in.yaml") + args + " --png-compression best --out " +
                    (dir_ / "never").string())
                .exit_code,
            2);
}

// A film whose memory would pass the bound (docs/limits.md) is refused before any work: stored
// frames of the largest size hold their whole file besides the framebuffers and the frame.
TEST_F(Cli, AFilmOverTheMemoryBoundIsRefusedBeforeAnyWork) {
  const fs::path out = dir_ / "never";
  for (const std::string& options :
       {std::string(" --png-compression stored"), std::string(" --png-compression small")}) {
    const CliRun r =
        parksim("run " + world("head_in.yaml") + " --frames --size 8192x8192 --view both" +
                options + " --out " + out.string());
    EXPECT_EQ(r.exit_code, 2) << r.out;
    EXPECT_NE(r.out.find("size 8192x8192, view both, png_compression " + options.substr(19)),
              std::string::npos)
        << r.out;
    EXPECT_NE(r.out.find("more than the bound of 1700000000"), std::string::npos) << r.out;
    EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 1) << r.out;
    EXPECT_FALSE(fs::exists(out));
  }
}

// The file names in OUT/figures, sorted; empty when there is no such directory.
std::vector<std::string> figureFiles(const fs::path& out) {
  std::vector<std::string> names;
  if (!fs::exists(out / "figures")) return names;
  for (const auto& e : fs::directory_iterator(out / "figures")) {
    names.push_back(e.path().filename().string());
  }
  std::sort(names.begin(), names.end());
  return names;
}

TEST_F(Cli, FiguresOptionChoosesTheFiguresOnRunAndRender) {
  using Names = std::vector<std::string>;
  // A list alone draws those figures without filming; a repeated name counts once.
  fs::path out = dir_ / "list";
  CliRun r = parksim("run " + world("head_in.yaml") + " --figures plan,lot_map,plan --out " +
                     out.string());
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_EQ(figureFiles(out), (Names{"lot_map.png", "plan_time-a-star.png"}));
  EXPECT_FALSE(fs::exists(out / "frames"));
  // none: frames without figures.
  out = dir_ / "none";
  r = parksim("run " + world("head_in.yaml") + " --frames --fps 1 --size 64x48 --figures none " +
              "--out " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_TRUE(fs::exists(out / "frames" / "000000.png"));
  EXPECT_FALSE(fs::exists(out / "figures"));
  // render: a figure its inputs do not allow (tracking_error needs --executed) is not drawn.
  out = dir_ / "render";
  r = parksim(
      "render " + world("head_in.yaml") +
      " --planner rrt --size 240x160 --figures cspace_slice,tracking_error,steering --out " +
      out.string());
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_EQ(figureFiles(out), (Names{"cspace_slice.png", "steering.png"}));
  out = dir_ / "render_none";
  ASSERT_EQ(parksim("render " + world("head_in.yaml") + " --planner rrt --figures none --out " +
                    out.string())
                .exit_code,
            0);
  EXPECT_TRUE(fs::exists(out / "plan_rrt.json"));
  EXPECT_FALSE(fs::exists(out / "figures"));
  // An unknown name: exit 2, one line listing the valid names, nothing written.
  for (const char* command : {"run ", "render "}) {
    out = dir_ / "never";
    r = parksim(command + world("head_in.yaml") + " --figures lot_map,lotmap --out " +
                out.string());
    EXPECT_EQ(r.exit_code, 2) << r.out;
    const std::size_t at = r.out.find("unknown figure 'lotmap'");
    ASSERT_NE(at, std::string::npos) << r.out;
    const std::string line = r.out.substr(at, r.out.find('\n', at) - at);
    for (std::string_view name : kFigureNames) {
      EXPECT_NE(line.find(name), std::string::npos) << line;
    }
    EXPECT_FALSE(fs::exists(out));
  }
}

TEST_F(Cli, BadInputToRunLeavesAnEarlierRunsOutputsAlone) {
  const fs::path out = dir_ / "run";
  ASSERT_EQ(parksim("run " + world("head_in.yaml") + " --out " + out.string()).exit_code, 0);
  const std::string executed = slurp(out / "executed.csv");
  const std::string metrics = slurp(out / "metrics.json");
  ASSERT_FALSE(executed.empty());
  EXPECT_EQ(parksim("run " + world("head_in.yaml") + " --plan " + (dir_ / "nope.csv").string() +
                    " --out " + out.string())
                .exit_code,
            2);
  EXPECT_EQ(
      parksim("run " + world("head_in.yaml") + " --planner nope --out " + out.string()).exit_code,
      2);
  EXPECT_EQ(slurp(out / "executed.csv"), executed);
  EXPECT_EQ(slurp(out / "metrics.json"), metrics);
}

TEST_F(Cli, UsageErrorsExitWithTwo) {
  EXPECT_EQ(parksim("").exit_code, 2);
  EXPECT_EQ(parksim("plan").exit_code, 2);  // world missing
  const std::string out = " --out " + (dir_ / "never").string();
  EXPECT_EQ(parksim("plan " + world("head_in.yaml") + " --no-such-option" + out).exit_code, 2);
  EXPECT_EQ(parksim("plan " + world("head_in.yaml") + " --seed -3" + out).exit_code, 2);
  EXPECT_FALSE(fs::exists(dir_ / "never"));
}

TEST_F(Cli, EveryCommandHasHelp) {
  for (const char* cmd : {"", "plan", "run", "render", "sweep", "merge", "report"}) {
    const CliRun r = parksim(std::string(cmd) + " --help");
    EXPECT_EQ(r.exit_code, 0) << cmd;
    EXPECT_NE(r.out.find("--help"), std::string::npos) << cmd;
  }
}

TEST_F(Cli, StartGoalAndSetOverrideTheWorldOnEveryWorldCommand) {
  const fs::path out = dir_ / "moved";
  CliRun r = parksim("plan " + world("head_in.yaml") +
                     " --start 0.2,0.15,45 --goal 1.5,0.05,-90 --set robot.max_wheel_speed_radps=8"
                     " --out " +
                     out.string());
  ASSERT_EQ(r.exit_code, 0) << r.out;
  const Trajectory t = readTrajectoryCsv((out / "trajectory.csv").string());
  EXPECT_EQ(t.points.front().pose.x, 0.2);
  EXPECT_EQ(t.points.front().pose.y, 0.15);
  EXPECT_LT(std::hypot(t.points.back().pose.x - 1.5, t.points.back().pose.y - 0.05), 1e-3);
  for (const TrajectoryPoint& p : t.points) {
    EXPECT_LE(std::abs(p.wheels.left_radps), 8.0 + 1e-9);
    EXPECT_LE(std::abs(p.wheels.right_radps), 8.0 + 1e-9);
  }
  // Checked like the file, named by the override, on run and render too; nothing written.
  for (const char* cmd : {"plan", "run", "render"}) {
    r = parksim(std::string(cmd) + " " + world("head_in.yaml") +
                " --set robot.wheel_radius=-1 --out " + (dir_ / "never").string());
    EXPECT_EQ(r.exit_code, 2) << cmd;
    EXPECT_EQ(r.out,
              "parksim: error: --set robot.wheel_radius=-1: robot.wheel_radius: must be positive, "
              "got -1\n")
        << cmd;
  }
  EXPECT_FALSE(fs::exists(dir_ / "never"));
}

TEST_F(Cli, QuietPrintsNothingAndVerboseTellsTheBuild) {
  const std::string out = " --out " + (dir_ / "q").string();
  CliRun r = parksim("plan " + world("head_in.yaml") + " -q" + out);
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_EQ(r.out, "");
  r = parksim("plan " + world("head_in.yaml") + " -v --seed 2" + out);
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_EQ(r.out.rfind(versionLine(buildProvenance()) + "\n", 0), 0u) << r.out;
  EXPECT_NE(r.out.find("--seed = 2"), std::string::npos) << r.out;
  // Errors still show under -q.
  r = parksim("plan " + world("head_in.yaml") + " -q --planner nope" + out);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.out.find("unknown planner 'nope'"), std::string::npos) << r.out;
}

TEST_F(Cli, MessagesSayWhatIsWrongInFewWords) {
  CliRun r = parksim("foo");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_EQ(r.out,
            "parksim: unknown command 'foo'; commands: plan, run, render, sweep, merge, report, "
            "compare, verify, list, import\n");
  // Bounds are stated, not printed as the 309-digit largest double.
  r = parksim("plan " + world("head_in.yaml") + " --seed -1");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.out.find("--seed: must be an integer in [0, 18446744073709551615], got '-1'"),
            std::string::npos)
      << r.out;
  r = parksim("run " + world("head_in.yaml") + " --fps 0");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.out.find("--fps: must be in (0, 1000], got '0'"), std::string::npos) << r.out;
  EXPECT_LT(r.out.size(), 200u) << r.out;
  // Usage lines name the program, not the path it was started from.
  r = parksim("plan --help");
  EXPECT_NE(r.out.find("Usage: parksim plan "), std::string::npos) << r.out;
  // render draws two planners by default, so --planner shows no single default.
  r = parksim("render --help");
  EXPECT_NE(r.out.find("--planner TEXT "), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("--planner TEXT="), std::string::npos) << r.out;
}

TEST_F(Cli, EveryCommandPrintsTheVersionAndBuild) {
  const Provenance build = buildProvenance();
  for (const char* cmd : {"", "plan", "run", "render", "sweep", "merge", "report"}) {
    const CliRun r = parksim(std::string(cmd) + " --version");
    EXPECT_EQ(r.exit_code, 0) << cmd;
    EXPECT_EQ(r.out, versionLine(build) + "\n") << cmd;
  }
  EXPECT_EQ(build.version, PARKSIM_PROJECT_VERSION);
  EXPECT_TRUE(build.bullet_precision == "float" || build.bullet_precision == "double");
  // Built from this repository's git tree: a full commit hash (the tests run from a checkout).
  EXPECT_EQ(build.git_commit.find_first_not_of("0123456789abcdef"), std::string::npos);
  EXPECT_EQ(build.git_commit.size(), 40u) << build.git_commit;
}

TEST_F(Cli, PlanAndRunFilesRecordTheBuild) {
  const fs::path out = dir_ / "run";
  ASSERT_EQ(parksim("run " + world("head_in.yaml") + " --out " + out.string()).exit_code, 0);
  const Provenance build = buildProvenance();
  const auto plan = nlohmann::json::parse(slurp(out / "plan.json"));
  const auto metrics = nlohmann::json::parse(slurp(out / "metrics.json"));
  for (const auto& [key, value] : provenanceFields(build)) {
    const nlohmann::json expected =
        key == "git_dirty" ? nlohmann::json(build.git_dirty) : nlohmann::json(value);
    EXPECT_EQ(plan["provenance"][key], expected) << key;
    EXPECT_EQ(metrics["provenance." + key], expected) << key;
  }
}

}  // namespace
}  // namespace parksim
