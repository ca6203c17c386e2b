// Hostile inputs and options, as a table: each case runs the parksim executable and expects an
// exit code and a message, a bounded run (every case under a time and memory limit), no raw
// control bytes on the terminal, a short message (no DBL_MAX printed in full), and an earlier
// run's --out left exactly as it was. docs/limits.md lists the limits these cases hit.

#include <fcntl.h>
#include <sys/file.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tests/support/RunParksim.h"
#include "tests/support/Sanitizers.h"
#include "tests/support/TestPaths.h"

namespace parksim {
namespace {

namespace fs = std::filesystem;
using testing::slurp;

struct Outcome {
  int exit_code;
  std::string out;
};

// An address-space cap in KiB (ulimit -v), or none under AddressSanitizer: its shadow memory
// alone is a reservation of terabytes, and it checks allocations itself.
std::string memoryCap(long kib) {
  return parksim::testing::kSanitized ? "" : "ulimit -v " + std::to_string(kib) + "; ";
}

// Runs `parksim ARGS` from a shell with `limits` (ulimit commands) first, bounded in time and
// memory.
Outcome run(const std::string& args, const std::string& limits = "") {
  const std::string cmd = memoryCap(4'000'000) + limits + " timeout 60 " +
                          parksim::testing::parksimExe() + " " + args + " 2>&1";
  FILE* pipe = popen(("/bin/bash -c '" + cmd + "'").c_str(), "r");
  if (pipe == nullptr) return {-1, "popen failed"};
  std::string out;
  char buf[4096];
  while (std::fgets(buf, sizeof buf, pipe)) out += buf;
  const int status = pclose(pipe);
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, out};
}

std::map<std::string, std::string> snapshot(const fs::path& dir) {
  std::map<std::string, std::string> files;
  if (!fs::exists(dir)) return files;
  for (const auto& e : fs::recursive_directory_iterator(dir)) {
    if (e.is_regular_file()) files[fs::relative(e.path(), dir).string()] = slurp(e.path());
  }
  return files;
}

void write(const fs::path& p, const std::string& text) {
  std::ofstream(p, std::ios::binary) << text;
}

const std::string kHeader = "t,x,y,theta,omega_left,omega_right,v,omega\n";
// head_in's start: (0.1, 0.1, 90 deg).
const std::string kStartRow = "0,0.1,0.1,1.5707963267948966,0,0,0,0\n";

class HostileInput : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = fs::temp_directory_path() / ("parksim_hostile_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    const std::string src = parksim::testing::sourceDir();
    const std::string corpus = src + "/tests/fuzz/corpus/";
    vars_ = {
        {"{W}", src + "/worlds/head_in.yaml"},
        {"{OUT}", (dir_ / "out").string()},
        {"{DIR}", dir_.string()},
        {"{C}", corpus},
    };
    write(dir_ / "long_plan.csv", [] {
      std::string s = kHeader;
      for (int t = 0; t <= 3600; t += 60) {
        s += std::to_string(t) + ",0.1,0.1,1.5707963267948966,0,0,0,0\n";
      }
      return s;
    }());
    write(dir_ / "too_many_rows.csv", [] {
      std::string s = kHeader;
      for (int i = 0; i <= 1'000'000; ++i) s += std::to_string(i * 1e-3) + ",0,0,0,0,0,0,0\n";
      return s;
    }());
    write(dir_ / "elsewhere.csv", kHeader + "0,1,1,0,0,0,0,0\n0.1,1,1,0,0,0,0,0\n");
    write(dir_ / "a_file", "not a directory");
    // Thousands of obstacles and of parked robots on one spot each: legal (docs/world-format.md,
    // overlaps are not checked), and Bullet used to keep a broadphase pair for every two of them.
    write(dir_ / "stacked.yaml", [] {
      std::string s =
          "format: parksim-world/1\nname: stacked\n"
          "lot: {x_min: 0.0, y_min: 0.0, x_max: 1.4, y_max: 1.0}\n"
          "start: [0.15, 0.85, 0]\ngoal: {pose: [0.7, 0.06, -90]}\nobstacles:\n";
      for (int i = 0; i < 2500; ++i) {
        s += "  - {name: o" + std::to_string(i) +
             ", kind: bollard, center: [1.3, 0.9], radius: 0.01}\n";
      }
      s += "parked_robots:\n";
      for (int i = 0; i < 1500; ++i)
        s += "  - {name: p" + std::to_string(i) + ", pose: [1.2, 0.5, 0]}\n";
      return s;
    }());
    // Bad maps (issue 32), each behind a world that is otherwise fine.
    const auto map_world = [](const std::string& name, const std::string& entry) {
      write(dir_ / name,
            "format: parksim-world/1\nname: m\nmap: [" + entry +
                "]\nlot: {x_min: 0, y_min: 0, x_max: 1, y_max: 1}\nstart: [0.5, 0.5, 0]\n"
                "goal: {pose: [0.6, 0.5, 0]}\n");
    };
    const std::string ros_yaml = "resolution: 0.05\norigin: [0, 0, 0]\n";
    write(dir_ / "truncated.pgm", "P5\n20 20\n255\n" + std::string(100, '\xfe'));
    write(dir_ / "truncated.yaml", "image: truncated.pgm\n" + ros_yaml);
    map_world("w_truncated.yaml", "{ros: truncated.yaml}");
    map_world("w_missing.yaml", "{ros: nothere.yaml}");
    write(dir_ / "long.pgm", "P5\n2 2\n255\n" + std::string(9, '\xfe'));
    write(dir_ / "long.yaml", "image: long.pgm\n" + ros_yaml);
    map_world("w_long.yaml", "{ros: long.yaml}");
    write(dir_ / "nan.yaml", "image: long.pgm\nresolution: .nan\norigin: [0, 0, 0]\n");
    map_world("w_nan.yaml", "{ros: nan.yaml}");
    write(dir_ / "huge.pgm", "P5\n100000 100000\n255\n");
    write(dir_ / "huge.yaml", "image: huge.pgm\n" + ros_yaml);
    map_world("w_huge.yaml", "{ros: huge.yaml}");
    write(dir_ / "huge.map", "type octile\nheight 100000\nwidth 100000\nmap\n");
    map_world("w_huge_grid.yaml", "{movingai: huge.map, cell: 0.05}");
    write(dir_ / "bad.svg",
          "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 10 10\">\n"
          "<path id=\"p\" d=\"M 0 0 L 1 1 B 2 2\"/></svg>\n");
    map_world("w_bad_svg.yaml", "{svg: bad.svg, scale: 0.1}");
    fs::create_directories(dir_ / "foreign");
    write(dir_ / "foreign" / "thesis.tex", "precious");
    // An earlier run, which no refused command may change.
    const Outcome earlier = run("plan " + vars_["{W}"] + " --seed 5 --out " + vars_["{OUT}"]);
    if (earlier.exit_code != 0) setup_error_ = earlier.out;
  }
  // A failure in SetUpTestSuite would show as every test skipped (ctest counts those as
  // passed), so each test fails on it instead.
  void SetUp() override { ASSERT_EQ(setup_error_, "") << "the earlier run failed"; }
  static void TearDownTestSuite() { fs::remove_all(dir_); }

  static std::string expand(std::string s) {
    for (const auto& [key, value] : vars_) {
      for (std::size_t at = s.find(key); at != std::string::npos; at = s.find(key, at)) {
        s.replace(at, key.size(), value);
      }
    }
    return s;
  }

  static fs::path dir_;
  static std::map<std::string, std::string> vars_;
  static std::string setup_error_;
};

fs::path HostileInput::dir_;
std::map<std::string, std::string> HostileInput::vars_;
std::string HostileInput::setup_error_;

struct Case {
  const char* args;  // {W} head_in.yaml, {OUT} the earlier run's --out, {C} the fuzz corpus
  int exit_code;
  const char* message;  // expected substring of the output
};

// Every case writes to {OUT} (or names it) after an earlier run left its files there.
const Case kCases[] = {
    // Options: exact numbers, no clamping, readable bounds.
    {"plan {W} --seed 18446744073709551616 --out {OUT}", 2,
     "--seed: must be an integer in [0, 18446744073709551615]"},
    {"plan {W} --seed -3 --out {OUT}", 2, "--seed: must be an integer in"},
    {"plan {W} --seed abc --out {OUT}", 2, "--seed: not an integer: 'abc'"},
    {"plan {W} --max-iterations 99999999999 --out {OUT}", 2, "[1, 1000000]"},
    {"plan {W} --max-iterations 0 --out {OUT}", 2, "expected auto or an integer in [1, 1000000]"},
    {"plan {W} --planner bogus --out {OUT}", 2, "unknown planner 'bogus'"},
    {"run {W} --frames --fps 0 --out {OUT}", 2, "--fps: must be in (0, 1000], got '0'"},
    {"run {W} --frames --fps nan --out {OUT}", 2, "--fps: must be a finite number in (0, 1000]"},
    {"run {W} --frames --fps inf --out {OUT}", 2, "--fps: must be a finite number"},
    {"run {W} --frames --fps 1e309 --out {OUT}", 2, "--fps: must be a finite number"},
    {"run {W} --frames --fps 1e9 --out {OUT}", 2, "--fps: must be in (0, 1000], got '1e9'"},
    {"run {W} --frames --fps abc --out {OUT}", 2, "--fps: not a number: 'abc'"},
    {"run {W} --frames --size 4294967936x480 --out {OUT}", 2, "size must be WxH"},
    {"run {W} --frames --size 640x --out {OUT}", 2, "size must be WxH"},
    {"render {W} --cspace-heading nan --out {OUT}", 2, "--cspace-heading: must be a finite"},
    {"render {W} --slices 0 --out {OUT}", 2, "--slices: must be an integer in [1, 720]"},
    {"render {W} --planner bogus --out {OUT}", 2, "unknown planner 'bogus'"},
    {"render {W} --executed {DIR}/missing.csv --out {OUT}", 2, "missing.csv: cannot open"},
    {"render {W} --executed /dev/zero --out {OUT}", 2, "not a regular file"},
    {"run {W} --tracking sideways --out {OUT}", 2, "--tracking"},
    // Overrides: given and empty is an error (it used to fall back silently to the file's pose).
    {"plan {W} --start \"\" --out {OUT}", 2,
     "--start : start: must be a list [x, y, yaw_deg] of 3 numbers or a map {x, y, yaw_deg}, got "
     "a list of 0"},
    {"plan {W} --goal \"\" --out {OUT}", 2, "--goal : goal.pose: must be a list"},
    {"plan {W} --set obstacles[99999999999].center=[1,1] --out {OUT}", 2,
     "obstacles[99999999999]: obstacles has 3 items"},
    {"plan {W} --set obstacles[-1].center=[1,1] --out {OUT}", 2,
     "list index must be a whole number >= 0"},
    {"plan {W} --set \"name=a: [b\" --out {OUT}", 2, "(syntax): end of sequence flow not found"},
    {"plan {W} --set name=, --out {OUT}", 2, "name: must be a string, got null"},
    {"plan {W} --start 0.1,0.1,1.5708 --out {OUT}", 2, "1.5708 looks like radians"},
    // Physics no simulation can integrate: Bullet's state became NaN at the first step and the
    // run printed "-nan mm" and a max tracking error of 0.000 mm, exit 4. Since issue 22 the
    // world reader refuses them (physical ranges); the simulation's own guard is tested in
    // tests/sim/EpisodeCommandTest.cpp.
    {"run {W} --set physics.gravity_mps2=1e300 --out {OUT}", 2,
     "physics.gravity_mps2: must be in [0.1, 100] m/s^2"},
    {"run {W} --set physics.wheel_mass_kg=1e300 --out {OUT}", 2,
     "physics.wheel_mass_kg: must be in [0.0001, 10000] kg"},
    // Issue 22: degenerate values that planned and then ended metres from the goal (exit 4).
    {"run {W} --set robot.wheel_base=1e-12 --out {OUT}", 2, "robot.wheel_base: must be in"},
    {"run {W} --set physics.chassis_mass_kg=1e-300 --out {OUT}", 2,
     "physics.chassis_mass_kg: must be in [0.001, 100000] kg"},
    {"run {W} --set physics.time_step_s=1000 --out {OUT}", 2,
     "physics.time_step_s: must be in [1e-05, 0.01] s"},
    {"run {W} --set robot.max_wheel_speed_radps=1e-300 --out {OUT}", 2,
     "robot.max_wheel_speed_radps: must be in [0.1, 1000] rad/s"},
    {"run {W} --set robot.length=5 --set robot.width=5 --out {OUT}", 2,
     "robot: turning a 5 x 5 m body on a 0.085 m wheel base"},
    // Plan files: type, size and content limits, checked before anything is written.
    {"run {W} --plan /dev/zero --out {OUT}", 2, "/dev/zero: is not a regular file"},
    {"run {W} --plan /dev/urandom --out {OUT}", 2, "is not a regular file"},
    {"run {W} --plan {DIR} --out {OUT}", 2, "is a directory, not a plan file"},
    {"run {W} --plan {DIR}/missing.csv --out {OUT}", 2, "cannot open plan file"},
    {"run {W} --plan {C}plan/time_1e300 --out {OUT}", 2, "column 't': must be in [0, 3600] s"},
    {"run {W} --plan {C}plan/gap_100 --out {OUT}", 2, "more than the limit of 60 s"},
    {"run {W} --plan {C}plan/long_line --out {OUT}", 2, "more than the limit of 4096"},
    {"run {W} --plan {C}plan/nan_x --out {OUT}", 2, "column 'x': 'nan' is not a finite number"},
    {"run {W} --plan {C}plan/huge_wheel --out {OUT}", 2, "column 'omega_left': must be within"},
    {"run {W} --plan {C}plan/empty --out {OUT}", 2, "empty trajectory file"},
    {"run {W} --plan {C}plan/header_only --out {OUT}", 2, "trajectory has no rows"},
    {"run {W} --plan {C}plan/time_not_increasing --out {OUT}", 2, "time does not increase"},
    {"run {W} --plan {C}plan/raw_bytes --out {OUT}", 2, "\\xFF\\x1B[31m"},
    {"run {W} --plan {DIR}/too_many_rows.csv --out {OUT}", 2,
     "more than the limit of 1000000 rows"},
    {"run {W} --plan {DIR}/elsewhere.csv --out {OUT}", 2, "not at the world's start"},
    // Work limits: physics steps, frames, steering profiles.
    {"run {W} --plan {DIR}/long_plan.csv --frames --fps 30 --out {OUT}", 2,
     "more than the limit of 50000"},
    {"run {C}world/tiny_time_step.yaml --out {OUT}", 2, "physics steps"},
    // A 1e-6 rad/s^2 wheel acceleration and a 1 nm wheel radius needed more than 100000
    // control periods; since issue 22 the world reader refuses them (physical ranges).
    {"plan {C}world/tiny_accel.yaml --steering rotate-translate-rotate --out {OUT}", 2,
     "tiny_accel.yaml:4: robot.max_wheel_accel_radps2: must be in [0.1, 10000] rad/s^2"},
    {"plan {C}world/tiny_wheel.yaml --steering rotate-translate-rotate --out {OUT}", 2,
     "tiny_wheel.yaml:4: robot.wheel_radius: must be in [0.001, 5] m"},
    {"plan {C}world/huge_lot.yaml --planner rrt --steering rotate-translate-rotate --out {OUT}", 2,
     "a straight move across the lot"},
    // World files (the reader's own limits, docs/world-format.md): bounded, one line, exit 2.
    {"plan {C}world/comma --out {OUT}", 2, "unexpected ','"},
    {"plan {C}world/two_documents --out {OUT}", 2, "(syntax)"},
    {"plan /dev/zero --out {OUT}", 2, "not a regular file"},
    {"plan {DIR} --out {OUT}", 2, "parksim: error:"},
    {"plan {C}world/yaw_1e308.yaml --out {OUT}", 2, "obstacles[2].yaw_deg: must be in"},
    {"plan {C}world/start_1e309.yaml --out {OUT}", 2, "start[2]"},
    {"plan {C}world/start_inf.yaml --out {OUT}", 2, "start[2]: must be a finite number"},
    {"plan {C}world/name_raw_bytes.yaml --out {OUT}", 2, "\\x1b[31mred"},
    // Bad maps (issue 32): one located line naming the map file, nothing written.
    {"plan {DIR}/w_truncated.yaml --out {OUT}", 2,
     "map[0].ros: {DIR}/truncated.pgm: truncated: the header says 20 x 20 pixels (400 bytes), "
     "the file holds 100 bytes after the header"},
    {"plan {DIR}/w_missing.yaml --out {OUT}", 2,
     "map[0].ros: {DIR}/nothere.yaml: cannot open ROS map YAML: No such file or directory"},
    {"plan {DIR}/w_long.yaml --out {OUT}", 2,
     "long.pgm: size mismatch: the header says 2 x 2 pixels (4 bytes), the file holds 9 bytes"},
    {"plan {DIR}/w_nan.yaml --out {OUT}", 2,
     "nan.yaml:2: resolution: must be a finite number, got .nan"},
    {"plan {DIR}/w_huge.yaml --out {OUT}", 2,
     "huge.pgm: the image is 100000 x 100000 pixels, more than the limit of 20000 a side"},
    {"run {DIR}/w_huge_grid.yaml --out {OUT}", 2,
     "huge.map:3: the map is 100000 x 100000 cells; a map has at least one and at most 20000"},
    {"render {DIR}/w_bad_svg.yaml --out {OUT}", 2,
     "bad.svg:2: path#p: d: unknown path command 'B'"},
    {"import {DIR}/nan.yaml --out {OUT}/imported.yaml", 2,
     "nan.yaml:2: resolution: must be a finite number, got .nan"},
    // Output locations.
    {"plan {W} --out {DIR}/a_file", 2, "exists and is not a directory"},
    {"plan {W} --out {DIR}/foreign", 2, "holds 'thesis.tex', which parksim did not write"},
    {"plan {W} --out /", 2, "needs a directory name"},
    // Write errors: a file-size limit ends in a message, not SIGXFSZ; nothing is left behind.
    {"ulimit:-f 1|run {W} --out {OUT}", 2, "File too large"},
};

TEST_F(HostileInput, EachCaseIsRefusedWithItsExitCodeAndMessageAndLeavesOutAlone) {
  const fs::path out = vars_["{OUT}"];
  const auto earlier = snapshot(out);
  ASSERT_FALSE(earlier.empty());
  for (const Case& c : kCases) {
    std::string args = c.args;
    std::string limits;
    if (args.rfind("ulimit:", 0) == 0) {
      const std::size_t bar = args.find('|');
      limits = "ulimit " + args.substr(7, bar - 7) + ";";
      args = args.substr(bar + 1);
    }
    const Outcome r = run(expand(args), limits);
    SCOPED_TRACE(c.args);
    EXPECT_EQ(r.exit_code, c.exit_code) << r.out;
    EXPECT_NE(r.out.find(expand(c.message)), std::string::npos)
        << "expected '" << c.message << "' in:\n"
        << r.out;
    EXPECT_EQ(r.out.find('\x1b'), std::string::npos) << "raw escape in the output: " << r.out;
    EXPECT_LT(r.out.size(), 400u) << "one short line expected: " << r.out;
    EXPECT_EQ(snapshot(out), earlier) << "the earlier run's --out changed";
    for (const auto& e : fs::directory_iterator(dir_)) {
      EXPECT_EQ(e.path().filename().string().find(".parksim-staging"), std::string::npos)
          << "staging left behind: " << e.path();
    }
  }
}

TEST_F(HostileInput, NamesAndPathsThatAreNotUtf8ReachJsonAndTheTerminalEscaped) {
  // A world at a path that is not UTF-8 and holds a terminal escape: the path reaches the
  // terminal and plan.json / metrics.json.
  const fs::path world = dir_ / "w\xff\x1b[31m.yaml";
  fs::copy_file(expand("{W}"), world, fs::copy_options::overwrite_existing);
  const fs::path out = dir_ / "utf8";
  const Outcome r = run("plan \"" + world.string() + "\" --out " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.out;
  EXPECT_EQ(r.out.find('\x1b'), std::string::npos) << r.out;
  if (r.exit_code == 0) {
    const auto plan = nlohmann::json::parse(slurp(out / "plan.json"));
    EXPECT_EQ(plan["status"], "solved");
    const Outcome run_r = run("run \"" + world.string() + "\" --out " + out.string());
    EXPECT_TRUE(run_r.exit_code == 0 || run_r.exit_code == 1) << run_r.out;
    EXPECT_EQ(run_r.out.find('\x1b'), std::string::npos) << run_r.out;
    EXPECT_TRUE(nlohmann::json::parse(slurp(out / "metrics.json")).is_object());
  }
}

TEST_F(HostileInput, ASecondCommandIntoALockedOutFailsAtOnce) {
  const fs::path out = dir_ / "locked";
  const std::string lock_path = (dir_ / ".locked.lock").string();
  const int fd = ::open(lock_path.c_str(), O_RDWR | O_CREAT, 0644);
  ASSERT_GE(fd, 0);
  ASSERT_EQ(::flock(fd, LOCK_EX | LOCK_NB), 0);
  const Outcome r = run("plan " + vars_["{W}"] + " --out " + out.string());
  ::close(fd);
  EXPECT_EQ(r.exit_code, 2) << r.out;
  EXPECT_NE(r.out.find("another parksim command is writing there"), std::string::npos) << r.out;
  EXPECT_FALSE(fs::exists(out));
  // Once the lock is free, the same command succeeds.
  EXPECT_EQ(run("plan " + vars_["{W}"] + " --out " + out.string()).exit_code, 0);
}

// 2,500 obstacles and 1,500 parked robots stacked on one spot each: 3.1 million and 1.1 million
// broadphase pairs made the planner's collision world and the simulation crash in 400 MB (and
// 10,000 parked robots on one spot ran out of 3 GB); fixed obstacles now never pair.
TEST_F(HostileInput, StackedObstaclesAndParkedRobotsCostNoPairs) {
  const Outcome r =
      run("run " + (dir_ / "stacked.yaml").string() + " --out " + (dir_ / "stacked").string(),
          memoryCap(400'000));
  EXPECT_EQ(r.exit_code, 0) << r.out;
}

TEST_F(HostileInput, AnUnsolvedPlanIsAResultAndReplacesTheEarlierOutputWhole) {
  const fs::path out = dir_ / "unsolved";
  ASSERT_EQ(run("run " + vars_["{W}"] + " --out " + out.string()).exit_code, 0);
  ASSERT_TRUE(fs::exists(out / "executed.csv"));
  const Outcome r =
      run("run " + vars_["{W}"] + " --planner rrt --max-iterations 1 --out " + out.string());
  EXPECT_EQ(r.exit_code, 1) << r.out;
  // The new outputs (plan.json of the unsolved plan, metrics.json of its verdict) and none of
  // the earlier run's.
  EXPECT_TRUE(fs::exists(out / "plan.json"));
  EXPECT_FALSE(fs::exists(out / "executed.csv"));
  EXPECT_FALSE(fs::exists(out / "trajectory.csv"));
  EXPECT_EQ(nlohmann::json::parse(slurp(out / "metrics.json"))["status"], "plan_failed");
}

}  // namespace
}  // namespace parksim
