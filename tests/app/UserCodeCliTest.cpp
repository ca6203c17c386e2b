// A user's plan, planner and controller through the command line (docs/your-code.md): a plan
// that collides or breaks a limit is never driven (exit 5), a plugin's component that crashes or
// hangs is a verdict (exit 6) with nothing written, and bad plugins, and a plugin's constructor
// that crashes or hangs as its parameters are checked, are one-line input errors.

#include <filesystem>
#include <fstream>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tests/support/RunParksim.h"
#include "tests/support/TestPaths.h"

namespace parksim {
namespace {

namespace fs = std::filesystem;
using testing::CliRun;
using ::testing::HasSubstr;
using ::testing::MatchesRegex;
using ::testing::Not;

class UserCodeCli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = testing::testOutputDir("user_code_cli") /
           ::testing::UnitTest::GetInstance()->current_test_info()->name();
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  std::string world(const std::string& name) const {
    return testing::sourceDir() + "/worlds/" + name + ".yaml";
  }
  std::string out(const std::string& sub) const { return (dir_ / sub).string(); }
  static std::string faulty() {
    return testing::binaryDir() + "/tests/plugin/libparksim_faulty_plugin.so";
  }
  static std::string examples() {
    return testing::binaryDir() + "/examples/plugins/libparksim_example_plugins.so";
  }
  // head_in with a 5 cm box dropped on the default plan's middle row (issue 30's example).
  std::string droppedBox() const {
    std::ifstream in(world("head_in"));
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::string key = "obstacles:\n";
    text.insert(text.find(key) + key.size(),
                "  - {name: dropped_box, kind: box, center: [0.752, 0.435], size: [0.05, 0.05]}\n");
    const std::string path = out("dropped_box.yaml");
    std::ofstream(path) << text;
    return path;
  }
  fs::path dir_;
};

TEST_F(UserCodeCli, ACollidingPlanFileIsInvalidAndNotDriven) {
  CliRun r = testing::runParksim("plan " + world("head_in") + " --out " + out("plan"));
  ASSERT_EQ(r.exit_code, 0) << r.out;
  r = testing::runParksim("run " + droppedBox() + " --plan " + out("plan") +
                          "/trajectory.csv --out " + out("run"));
  EXPECT_EQ(r.exit_code, 5) << r.out;
  EXPECT_THAT(r.out, MatchesRegex("(.|\n)*parksim run: plan_invalid: at t = [0-9.]+ s \\(x [0-9.]+ "
                                  "m, y [0-9.]+ m, -?[0-9.]+ deg\\) the footprint overlaps "
                                  "dropped_box\n"));
  EXPECT_FALSE(fs::exists(dir_ / "run" / "executed.csv"));
  // Its metrics.json holds the verdict and the file's name.
  std::ifstream in(dir_ / "run" / "metrics.json");
  const nlohmann::json m = nlohmann::json::parse(in);
  EXPECT_EQ(m["status"], "plan_invalid");
  EXPECT_NE(m["plan_source"].get<std::string>().find("trajectory.csv"), std::string::npos);
  // Over the world's wheel-speed limit: the limit is named.
  r = testing::runParksim("run " + world("head_in") + " --plan " + out("plan") +
                          "/trajectory.csv --set robot.max_wheel_speed_radps=5 --out " +
                          out("slow"));
  EXPECT_EQ(r.exit_code, 5) << r.out;
  EXPECT_THAT(r.out, HasSubstr("exceed robot.max_wheel_speed_radps 5"));
}

// One check for every command: a plugin's plan through a wall is plan_invalid from plan, run and
// render alike (exit 5); none says "solved", writes the plan as one to drive, or draws it.
TEST_F(UserCodeCli, APlanThroughAWallIsInvalidFromEveryCommand) {
  for (const std::string command : {"plan", "run", "render"}) {
    SCOPED_TRACE(command);
    const CliRun r =
        testing::runParksim(command + " " + world("head_in") + " --plugin " + faulty() +
                            " --planner through-walls --out " + out(command));
    EXPECT_EQ(r.exit_code, 5) << r.out;
    EXPECT_THAT(r.out, MatchesRegex("(.|\n)*parksim " + command +
                                    ": plan_invalid: at t = [0-9.]+ s \\(x [0-9.]+ m, y [0-9.]+ "
                                    "m, -?[0-9.]+ deg\\) the footprint overlaps [a-z_0-9, ]+\n"));
    EXPECT_THAT(r.out, Not(HasSubstr("solved")));
    EXPECT_FALSE(fs::exists(dir_ / command / "trajectory.csv"));
    EXPECT_FALSE(fs::exists(dir_ / command / "figures"));
  }
  // plan and run record the verdict and whose code it was; run its metrics.json too.
  for (const std::string command : {"plan", "run"}) {
    std::ifstream in(dir_ / command / "plan.json");
    const nlohmann::json plan = nlohmann::json::parse(in);
    EXPECT_EQ(plan["status"], "plan_invalid");
    EXPECT_THAT(plan["planner_origin"].get<std::string>(),
                HasSubstr("plugin parksim-faults 0.1 ("));
  }
  std::ifstream in(dir_ / "run" / "metrics.json");
  EXPECT_EQ(nlohmann::json::parse(in)["status"], "plan_invalid");
}

TEST_F(UserCodeCli, CrashesAndHangsOfPluginCodeAreVerdictsWithNothingWritten) {
  for (const std::string& args :
       {" --controller segfault-controller", " --controller hanging-controller",
        " --planner segfault-planner", " --planner hanging-planner"}) {
    SCOPED_TRACE(args);
    const CliRun r = testing::runParksim(
        "run " + world("head_in") + " --plugin " + faulty() + args +
        " --planner-timeout 0.5 --controller-timeout 0.5 --out " + out("crash"));
    EXPECT_EQ(r.exit_code, 6) << r.out;
    const bool planner = args.find("planner") != std::string::npos;
    EXPECT_THAT(r.out, HasSubstr(std::string("parksim run: ") + (planner ? "planner_error: planner "
                                                                         : "controller_error: "
                                                                           "controller ")));
    EXPECT_FALSE(fs::exists(dir_ / "crash"));
  }
  // One that throws is caught in the process: its record up to the failure is kept.
  const CliRun r = testing::runParksim("run " + world("head_in") + " --plugin " + faulty() +
                                       " --controller throwing-controller --out " + out("throw"));
  EXPECT_EQ(r.exit_code, 6) << r.out;
  EXPECT_THAT(r.out, HasSubstr("controller_error: controller throwing-controller threw in command "
                               "at t = 1.000 s: lost track"));
  EXPECT_TRUE(fs::exists(dir_ / "throw" / "executed.csv"));
}

// Checking the parameters makes the component: a plugin's constructor that crashes or hangs is
// bad input named in one line (exit 2), not the end of parksim, and nothing is written.
TEST_F(UserCodeCli, ConstructorsThatCrashOrHangAreOneLineErrorsWithNothingWritten) {
  struct Case {
    const char* args;
    const char* message;
  };
  for (const Case& c :
       {Case{" --planner segfault-ctor-planner",
             "planner segfault-ctor-planner crashed (SIGSEGV, Segmentation fault)"},
        Case{" --controller segfault-ctor-controller",
             "controller segfault-ctor-controller crashed (SIGSEGV, Segmentation fault)"},
        Case{" --planner hanging-ctor-planner",
             "planner hanging-ctor-planner ran past its time limit of 0.5 s (its process was "
             "killed)"},
        Case{" --controller hanging-ctor-controller",
             "controller hanging-ctor-controller gave no command within its time limit of 0.5 s "
             "(its process was killed)"}}) {
    SCOPED_TRACE(c.args);
    const CliRun r =
        testing::runParksim("run " + world("head_in") + " --plugin " + faulty() + c.args +
                            " --planner-timeout 0.5 --controller-timeout 0.5 --out " + out("ctor"));
    EXPECT_EQ(r.exit_code, 2) << r.out;
    EXPECT_EQ(r.out, std::string("parksim: error: ") + c.message +
                         " while being made to check its parameters\n");
    EXPECT_FALSE(fs::exists(dir_ / "ctor"));
  }
  // Made without its fault, the same component runs (its plan goes through the walls).
  const CliRun r = testing::runParksim("run " + world("head_in") + " --plugin " + faulty() +
                                       " --controller segfault-ctor-controller --controller-param "
                                       "fault_above=1 --out " +
                                       out("sound"));
  EXPECT_EQ(r.exit_code, 0) << r.out;
  EXPECT_TRUE(fs::exists(dir_ / "sound" / "executed.csv"));
}

TEST_F(UserCodeCli, PluginsAreListedAndSelectedByName) {
  CliRun r = testing::runParksim("list --plugin " + examples());
  EXPECT_EQ(r.exit_code, 0) << r.out;
  EXPECT_THAT(r.out, HasSubstr("  example "));
  EXPECT_THAT(r.out, HasSubstr("  pure-pursuit "));
  EXPECT_THAT(r.out, HasSubstr("plugin parksim-examples 1.0.0: "));
  r = testing::runParksim("run " + world("parallel") + " --plugin " + examples() +
                          " --planner example --controller pure-pursuit --out " + out("ex"));
  EXPECT_EQ(r.exit_code, 0) << r.out;
  // Unknown names and parameters, and files that are not plugins: one line, exit 2, nothing.
  for (const std::string& args :
       {std::string(" --planner exampel --plugin ") + examples(),
        std::string(" --controller pure-pursuit"),
        std::string(" --controller-param bandwith_radps=3"),
        std::string(" --plugin ") + world("head_in"), std::string(" --plugin /no/such.so")}) {
    SCOPED_TRACE(args);
    r = testing::runParksim("run " + world("head_in") + args + " --out " + out("bad"));
    EXPECT_EQ(r.exit_code, 2) << r.out;
    EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 1) << r.out;
    EXPECT_FALSE(fs::exists(dir_ / "bad"));
  }
}

}  // namespace
}  // namespace parksim
