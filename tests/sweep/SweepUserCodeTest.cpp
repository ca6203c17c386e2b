// Sweeps of user code end to end (docs/your-code.md): a plugin's planner and controller beside
// parksim's own, sharded and merged to the same rows; a faulty controller that crashes its
// process in one episode of a hundred, killed in the middle and resumed; a rebuilt plugin
// refused on resume; a planner that is a command in another language, and its time limit.

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <thread>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tests/support/RunParksim.h"
#include "tests/sweep/SweepTestSupport.h"

namespace parksim {
// Named, not anonymous: its program is compiled as one unity batch, where another file's
// helpers of the same names would meet these.
namespace sweep_user_code_test {

namespace fs = std::filesystem;
using testing::runParksim;
using testing::scratchDir;
using testing::slurp;
using testing::writeText;

std::string faulty() { return testing::binaryDir() + "/tests/plugin/libparksim_faulty_plugin.so"; }
std::string examples() {
  return testing::binaryDir() + "/examples/plugins/libparksim_example_plugins.so";
}
std::string world(const std::string& name) {
  return testing::sourceDir() + "/worlds/" + name + ".yaml";
}

std::vector<nlohmann::json> rows(const std::string& jsonl) {
  std::vector<nlohmann::json> out;
  std::istringstream in(slurp(jsonl));
  for (std::string line; std::getline(in, line);) {
    if (!line.empty()) out.push_back(nlohmann::json::parse(line));
  }
  return out;
}

// What a row measured and chose: none of the wall times that differ from run to run.
nlohmann::json stable(const nlohmann::json& row) {
  nlohmann::json out;
  for (const char* key : {"planner", "controller", "seed", "status", "failure", "max_pos_err_m",
                          "rms_pos_err_m", "final_x_m", "final_y_m", "final_theta_rad", "steps",
                          "plan_path_length_m", "plan_iterations", "plugins", "world_hash"}) {
    out[key] = row.at(key);
  }
  return out;
}

std::map<std::string, nlohmann::json> byId(const std::vector<nlohmann::json>& rs) {
  std::map<std::string, nlohmann::json> out;
  for (const nlohmann::json& r : rs) out[r["episode_id"].get<std::string>()] = stable(r);
  return out;
}

TEST(SweepUserCode, APluginsComponentsSweepBesideParksimsAndShardToTheSameRows) {
  const std::string dir = scratchDir();
  writeText(dir + "/spec.yaml", "format: parksim-sweep/1\nname: plugin\nworlds: [" +
                                    world("parallel") + "]\nplugins: [" + examples() +
                                    "]\nplanners: [time-a-star, example]\n"
                                    "controllers: [tracking, pure-pursuit]\nseeds: [1, 2]\n");
  const auto whole = runParksim("sweep " + dir + "/spec.yaml --out " + dir + "/whole");
  ASSERT_EQ(whole.exit_code, 0) << whole.out;
  const std::vector<nlohmann::json> all = rows(dir + "/whole/results.jsonl");
  ASSERT_EQ(all.size(), 8u);
  std::set<std::pair<std::string, std::string>> pairs;
  for (const nlohmann::json& r : all) {
    pairs.emplace(r["planner"], r["controller"]);
    EXPECT_EQ(r["status"], "met") << r.dump();
    // Every row names the plugin's code: name, version and the file's hash.
    EXPECT_EQ(r["plugins"].get<std::string>().rfind("parksim-examples 1.0.0 ", 0), 0u) << r.dump();
  }
  EXPECT_EQ(pairs.size(), 4u);
  // The same episodes in two shards, merged: the same rows.
  for (int i = 0; i < 2; ++i) {
    const auto r = runParksim("sweep " + dir + "/spec.yaml --out " + dir + "/split/shards/" +
                              std::to_string(i) + " --shard " + std::to_string(i) + "/2");
    ASSERT_EQ(r.exit_code, 0) << r.out;
  }
  const auto merged = runParksim("merge " + dir + "/split");
  ASSERT_EQ(merged.exit_code, 0) << merged.out;
  EXPECT_EQ(byId(rows(dir + "/split/results.jsonl")), byId(all));
  // metrics.json of one such episode names the plugin too.
  const auto run = runParksim("run " + world("parallel") + " --plugin " + examples() +
                              " --planner example --out " + dir + "/one");
  ASSERT_EQ(run.exit_code, 0) << run.out;
  EXPECT_EQ(nlohmann::json::parse(slurp(dir + "/one/metrics.json"))["provenance.plugins"],
            all.front()["plugins"]);
}

// Starts the sweep and kills it (SIGKILL) once it has written `at_least` rows, or when it ends.
void sweepThenKill(const std::string& spec, const std::string& out, std::size_t at_least) {
  const std::string exe = testing::parksimExe();
  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    freopen("/dev/null", "w", stdout);
    freopen("/dev/null", "w", stderr);
    execl(exe.c_str(), exe.c_str(), "sweep", spec.c_str(), "--out", out.c_str(), "--workers", "2",
          static_cast<char*>(nullptr));
    _exit(127);
  }
  for (int i = 0; i < 20000; ++i) {
    const std::string t = fs::exists(out + "/results.jsonl") ? slurp(out + "/results.jsonl") : "";
    if (static_cast<std::size_t>(std::count(t.begin(), t.end(), '\n')) >= at_least) break;
    if (waitpid(child, nullptr, WNOHANG) == child) return;
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  kill(child, SIGKILL);
  waitpid(child, nullptr, 0);
}

TEST(SweepUserCode, OneCrashingEpisodeOfAHundredIsAVerdictAndTheSweepResumes) {
  const std::string dir = scratchDir();
  // A hundred starts 0.1 mm apart along x; the controller crashes (SIGSEGV) in the last alone.
  std::string offsets = "start_offsets: [";
  for (int i = 0; i < 100; ++i) {
    offsets += (i > 0 ? ", [" : "[") + std::to_string(i * 1e-4) + ", 0, 0]";
  }
  writeText(dir + "/spec.yaml",
            "format: parksim-sweep/1\nname: faulty\nworlds: [" + world("head_in") +
                "]\nplugins: [" + faulty() +
                "]\ncontrollers: [{name: segfault-controller, params: {start_x_above_m: "
                "0.10985}}]\n" +
                offsets + "]\n");
  const std::string out = dir + "/out";
  sweepThenKill(dir + "/spec.yaml", out, 30);
  const auto again = runParksim("sweep " + dir + "/spec.yaml --out " + out + " --workers 2");
  EXPECT_EQ(again.exit_code, 1) << again.out;
  EXPECT_NE(again.out.find("99 met their tolerance, 1 did not"), std::string::npos) << again.out;
  const std::vector<nlohmann::json> all = rows(out + "/results.jsonl");
  ASSERT_EQ(all.size(), 100u);
  std::set<std::string> ids;
  for (const nlohmann::json& r : all) {
    ids.insert(r["episode_id"].get<std::string>());
    if (r["status"] == "met") continue;
    EXPECT_EQ(r["status"], "controller_error");
    EXPECT_EQ(r["failure"], "controller segfault-controller crashed (SIGSEGV, Segmentation fault)");
    EXPECT_EQ(r["controller"], "segfault-controller");
  }
  EXPECT_EQ(ids.size(), 100u);
  // Resumed again: nothing with a verdict runs again.
  const auto third = runParksim("sweep " + dir + "/spec.yaml --out " + out);
  EXPECT_NE(third.out.find("100 episodes, 0 run now"), std::string::npos) << third.out;
  EXPECT_EQ(rows(out + "/results.jsonl").size(), 100u);
}

TEST(SweepUserCode, AnotherBuildOfThePluginIsRefusedOnResume) {
  const std::string dir = scratchDir();
  const std::string copy = dir + "/libmine.so";
  fs::copy_file(examples(), copy);
  writeText(dir + "/spec.yaml",
            "format: parksim-sweep/1\nname: mine\nworlds: [" + world("parallel") +
                "]\nplugins: [libmine.so]\nplanners: [example]\nseeds: [1, 2]\n");
  auto r = runParksim("sweep " + dir + "/spec.yaml --out " + dir + "/out --shard 0/2");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  std::ofstream(copy, std::ios::app) << "rebuilt";
  r = runParksim("sweep " + dir + "/spec.yaml --out " + dir + "/out");
  EXPECT_EQ(r.exit_code, 2) << r.out;
  EXPECT_NE(r.out.find("resuming would mix results of two builds"), std::string::npos) << r.out;
  EXPECT_EQ(rows(dir + "/out/results.jsonl").size(), 1u);
}

TEST(SweepUserCode, APlannerInAnotherLanguageSweepsAsACommand) {
  const std::string dir = scratchDir();
  writeText(dir + "/spec.yaml",
            "format: parksim-sweep/1\nname: command\nworlds: [" + world("head_in") +
                "]\nplanners: [time-a-star, {command: [python3, " + testing::sourceDir() +
                "/examples/commands/waypoint_planner.py, '{problem}', '{out}'], params: "
                "{waypoints: '0.1 0.5, 0.8 0.5'}}]\n");
  const auto r = runParksim("sweep " + dir + "/spec.yaml --out " + dir + "/out");
  const std::vector<nlohmann::json> all = rows(dir + "/out/results.jsonl");
  ASSERT_EQ(all.size(), 2u) << r.out;
  for (const nlohmann::json& row : all) {
    EXPECT_TRUE(row["status"] == "met" || row["status"] == "plan_invalid") << row.dump();
    if (row["planner"] == "command") {
      EXPECT_NE(row["planner.command"].get<std::string>().find("waypoint_planner.py"),
                std::string::npos);
      EXPECT_NE(row["status"], "planner_error") << row.dump();
    }
  }
  // A command that is not there is refused at its line, before anything is written.
  writeText(dir + "/bad.yaml", "format: parksim-sweep/1\nname: bad\nworlds: [" + world("head_in") +
                                   "]\nplanners:\n  - {command: [./nope]}\n");
  const auto bad = runParksim("sweep " + dir + "/bad.yaml --out " + dir + "/bad");
  EXPECT_EQ(bad.exit_code, 2) << bad.out;
  EXPECT_NE(bad.out.find("bad.yaml:5: planners[0]: "), std::string::npos) << bad.out;
  EXPECT_FALSE(fs::exists(dir + "/bad"));
}

// The one plan check in a sweep: a plugin's plan through a wall is the row's plan_invalid, its
// plan's status too, and the episode's files say so and name the plugin.
TEST(SweepUserCode, APlanThroughAWallIsInvalidInItsRowAndItsFiles) {
  const std::string dir = scratchDir();
  writeText(dir + "/spec.yaml",
            "format: parksim-sweep/1\nname: wall\nworlds: [" + world("head_in") + "]\nplugins: [" +
                faulty() + "]\nplanners: [through-walls]\nrecord: {executed_csv: failures}\n");
  const auto r = runParksim("sweep " + dir + "/spec.yaml --out " + dir + "/out");
  EXPECT_EQ(r.exit_code, 1) << r.out;
  const std::vector<nlohmann::json> all = rows(dir + "/out/results.jsonl");
  ASSERT_EQ(all.size(), 1u) << r.out;
  EXPECT_EQ(all[0]["status"], "plan_invalid");
  EXPECT_EQ(all[0]["plan_status"], "plan_invalid");
  EXPECT_EQ(all[0]["plan_solved"], false);
  const std::string episode = dir + "/out/episodes/" + all[0]["episode_id"].get<std::string>();
  const nlohmann::json plan = nlohmann::json::parse(slurp(episode + "/plan.json"));
  EXPECT_NE(plan["planner_origin"].get<std::string>().find("plugin parksim-faults 0.1 ("),
            std::string::npos);
  EXPECT_EQ(nlohmann::json::parse(slurp(episode + "/metrics.json"))["status"], "plan_invalid");
  EXPECT_FALSE(fs::exists(episode + "/trajectory.csv"));
}

// A sweep's --planner-timeout stops a command planner's program too: that episode's
// planner_error names the limit (under `timeout 25`: a limit that does nothing fails here).
TEST(SweepUserCode, ThePlannerTimeLimitStopsACommand) {
  const std::string dir = scratchDir();
  writeText(dir + "/spec.yaml",
            "format: parksim-sweep/1\nname: slow\nworlds: [" + world("head_in") +
                "]\nplanners: [{command: [sh, -c, 'sleep 60', sh, '{out}']}]\n");
  const auto r =
      testing::runProgram("timeout 25 " + testing::parksimExe(),
                          "sweep " + dir + "/spec.yaml --planner-timeout 1 --out " + dir + "/out");
  EXPECT_EQ(r.exit_code, 1) << r.out;  // an episode failed
  const std::vector<nlohmann::json> all = rows(dir + "/out/results.jsonl");
  ASSERT_EQ(all.size(), 1u) << r.out;
  EXPECT_EQ(all[0]["status"], "planner_error");
  EXPECT_EQ(all[0]["failure"],
            "planner command `sh -c 'sleep 60' sh {out}` gave no answer within the planner time "
            "limit of 1 s and was killed");
}

// The spec's components are made to check their parameters: a plugin's constructor that crashes
// for some values, or hangs, is refused at the spec's line (or with the sampled values that
// crash it), before anything is written.
TEST(SweepUserCode, ConstructorsThatCrashOrHangAreRefusedAtTheirLine) {
  const std::string dir = scratchDir();
  const std::string head = "format: parksim-sweep/1\nname: ctor\nworlds: [" + world("head_in") +
                           "]\nplugins: [" + faulty() + "]\n";
  struct Case {
    std::string body;
    std::string message;  // what follows the spec's path; "..." stands for a sampled value
  };
  // segfault-ctor-planner crashes when its `value` exceeds `fault_above`.
  const std::string crash = "planner segfault-ctor-planner crashed (SIGSEGV, Segmentation fault)";
  for (const Case& c :
       {Case{"planners:\n  - {name: segfault-ctor-planner, params: {value: 0.2, fault_above: 0.5}}"
             "\n  - {name: segfault-ctor-planner, params: {value: 0.8, fault_above: 0.5}}\n",
             "spec.yaml:7: planners[1]: " + crash},
        Case{"planners: [{name: segfault-ctor-planner, params: {fault_above: 0.5}}]\nset:\n"
             "  planner.value: [0.2, 0.8]\n",
             "spec.yaml:7: planner.value=0.8: " + crash},
        // Drawn values are made as the episodes expand: the first episode's that crashes.
        Case{"planners: [{name: segfault-ctor-planner, params: {fault_above: 0.5}}]\nset:\n"
             "  planner.value: {uniform: [0, 1]}\nsamples: {count: 20, seed: 1}\n",
             "spec.yaml:7: set: planner.value=...: " + crash},
        Case{"controllers: [hanging-ctor-controller]\n",
             "spec.yaml:5: controllers[0]: controller hanging-ctor-controller gave no command "
             "within its time limit of 0.5 s (its process was killed)"}}) {
    SCOPED_TRACE(c.body);
    writeText(dir + "/spec.yaml", head + c.body);
    const auto r =
        runParksim("sweep " + dir + "/spec.yaml --controller-timeout 0.5 --out " + dir + "/out");
    EXPECT_EQ(r.exit_code, 2) << r.out;
    const std::string expected =
        "parksim: error: " + dir + "/" + c.message + " while being made to check its parameters\n";
    const std::size_t dots = expected.find("...");
    if (dots == std::string::npos) {
      EXPECT_EQ(r.out, expected);
    } else {
      // The value drawn (above 0.5) and its sample, e.g. "0.7736 (sample 3)".
      const std::string before = expected.substr(0, dots);
      const std::string after = expected.substr(dots + 3);
      ASSERT_EQ(r.out.rfind(before, 0), 0u) << r.out;
      ASSERT_GE(r.out.size(), before.size() + after.size()) << r.out;
      EXPECT_EQ(r.out.substr(r.out.size() - after.size()), after) << r.out;
      const std::string drawn =
          r.out.substr(before.size(), r.out.size() - before.size() - after.size());
      EXPECT_THAT(drawn, ::testing::MatchesRegex("0\\.[0-9]+ \\(sample [0-9]+\\)"));
      EXPECT_GT(std::stod(drawn), 0.5);
    }
    EXPECT_FALSE(fs::exists(dir + "/out"));
  }
}

}  // namespace sweep_user_code_test
}  // namespace parksim
