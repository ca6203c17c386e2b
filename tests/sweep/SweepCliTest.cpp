// `parksim sweep`, `merge` and `report` end to end, including a real kill in the middle.

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <map>
#include <thread>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tests/support/RunParksim.h"
#include "tests/sweep/SweepTestSupport.h"

namespace parksim {
namespace {

namespace fs = std::filesystem;
using testing::runParksim;
using testing::scratchDir;
using testing::slurp;
using testing::studySpec;
using testing::writeText;

std::size_t lines(const std::string& path) {
  const std::string t = slurp(path);
  return static_cast<std::size_t>(std::count(t.begin(), t.end(), '\n'));
}

std::map<std::string, int> idCounts(const std::string& jsonl) {
  std::map<std::string, int> counts;
  std::size_t start = 0;
  const std::string text = slurp(jsonl);
  while (start < text.size()) {
    const std::size_t nl = text.find('\n', start);
    const auto row = nlohmann::json::parse(text.substr(start, nl - start));
    ++counts[row["episode_id"].get<std::string>()];
    start = nl + 1;
  }
  return counts;
}

// Starts `parksim sweep SPEC --out OUT --workers 1` and kills it (SIGKILL) once it has written
// `rows` rows, or whenever it gets there: the assertions after it hold either way.
void sweepThenKill(const std::string& spec, const std::string& out, std::size_t rows) {
  const std::string exe = testing::parksimExe();
  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    const int devnull = ::open("/dev/null", O_WRONLY);
    dup2(devnull, 1);
    dup2(devnull, 2);
    execl(exe.c_str(), exe.c_str(), "sweep", spec.c_str(), "--out", out.c_str(), "--workers", "1",
          static_cast<char*>(nullptr));
    _exit(127);
  }
  for (int i = 0; i < 4000 && lines(out + "/results.jsonl") < rows; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  kill(child, SIGKILL);
  int status = 0;
  waitpid(child, &status, 0);
}

TEST(SweepCli, BadSpecExitsTwoWithALocatedErrorAndWritesNothing) {
  const std::string dir = scratchDir();
  writeText(dir + "/bad.yaml", studySpec("planners: [rrt, nope]\n"));
  const auto r = runParksim("sweep " + dir + "/bad.yaml --out " + dir + "/out");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.out.find("bad.yaml:4: planners[1]: unknown planner 'nope'"), std::string::npos)
      << r.out;
  EXPECT_FALSE(fs::exists(dir + "/out"));
}

TEST(SweepCli, SurvivesAKillAndCompletesEachEpisodeOnceThenReports) {
  const std::string dir = scratchDir();
  writeText(dir + "/spec.yaml", studySpec("planners: rrt-goal-connect\nseeds: {from: 1, to: 6}\n"));
  const std::string out = dir + "/out";
  sweepThenKill(dir + "/spec.yaml", out, 2);

  const auto again = runParksim("sweep " + dir + "/spec.yaml --out " + out + " --workers 2");
  EXPECT_EQ(again.exit_code, 0) << again.out;
  const std::map<std::string, int> counts = idCounts(out + "/results.jsonl");
  EXPECT_EQ(counts.size(), 6u);
  for (const auto& [id, n] : counts) EXPECT_EQ(n, 1) << id;
  EXPECT_EQ(lines(out + "/results.csv"), 7u);

  const auto report = runParksim("report " + out);
  EXPECT_EQ(report.exit_code, 0) << report.out;
  for (const char* f : {"summary.md", "summary.csv", "success_matrix.png", "tracking_error.png",
                        "plan_time.png", "path_length.png", "duration.png"}) {
    EXPECT_TRUE(fs::exists(out + "/report/" + f)) << f;
  }
  EXPECT_NE(slurp(out + "/report/summary.md")
                .find("| head_in | rrt-goal-connect+smooth | world | 6 | 6/6"),
            std::string::npos);
  // The report is an output directory like plan's: written again whole, and never into a
  // directory of other files (it used to drop its files into any --out, the sweep's own too).
  EXPECT_EQ(runParksim("report " + out).exit_code, 0);
  const auto into_sweep = runParksim("report " + out + " --out " + out);
  EXPECT_EQ(into_sweep.exit_code, 2) << into_sweep.out;
  EXPECT_NE(into_sweep.out.find("which parksim did not write"), std::string::npos)
      << into_sweep.out;
  EXPECT_FALSE(fs::exists(out + "/summary.md"));
  // Planner Arena's reader: one run line and one progress line (cost over time) per episode.
  const std::string log = slurp(out + "/report/ompl_head_in.log");
  EXPECT_NE(log.find("6 runs per planner"), std::string::npos) << log;
  EXPECT_NE(log.find("2 progress properties for each run\nbest cost REAL\ntime REAL\n6 runs\n"),
            std::string::npos)
      << log;
}

TEST(SweepCli, ExitsOneWhenAnEpisodeMissesItsToleranceAndShardsMerge) {
  const std::string dir = scratchDir();
  // A 0.1 um bound on the tracking error: every episode runs and misses it.
  writeText(dir + "/spec.yaml",
            studySpec("seeds: [1, 2, 3, 4]\ntolerance: {max_pos_err_m: 1.0e-7}\n"));
  const std::string out = dir + "/out";
  for (int i = 0; i < 2; ++i) {
    const auto r = runParksim("sweep " + dir + "/spec.yaml --out " + out + "/shards/" +
                              std::to_string(i) + " --shard " + std::to_string(i) + "/2");
    EXPECT_EQ(r.exit_code, 1) << r.out;
    EXPECT_NE(r.out.find("tracking tolerance not met: max_pos_err_m"), std::string::npos) << r.out;
  }
  const auto merged = runParksim("merge " + out);
  EXPECT_EQ(merged.exit_code, 0) << merged.out;
  EXPECT_NE(merged.out.find("4 episodes of 4 expected, 0 missing"), std::string::npos)
      << merged.out;
  EXPECT_EQ(lines(out + "/results.csv"), 5u);
  // A table in --out that is not a source was replaced, its episodes lost (hostile pass).
  const auto over = runParksim("merge " + out + "/shards/0 --out " + out + "/shards/1");
  EXPECT_EQ(over.exit_code, 2) << over.out;
  EXPECT_NE(over.out.find("already holds results.jsonl, which is not among the sources"),
            std::string::npos)
      << over.out;
  EXPECT_EQ(lines(out + "/shards/1/results.jsonl"), 2u);
  fs::remove_all(out + "/shards/1");
  const auto partial = runParksim("merge " + out);
  EXPECT_EQ(partial.exit_code, 1);
  EXPECT_NE(partial.out.find("2 missing"), std::string::npos) << partial.out;
}

TEST(SweepCli, SlurmWritesAResubmittableArrayScript) {
  const std::string dir = scratchDir();
  writeText(dir + "/spec.yaml", studySpec("seeds: {from: 1, to: 5}\n"));
  const auto r = runParksim("sweep " + dir + "/spec.yaml --out " + dir +
                            "/out --slurm --slurm-shards 3 --slurm-time 00:10:00 "
                            "--slurm-partition debug");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  const std::string script = slurp(dir + "/out/sweep.sbatch");
  EXPECT_NE(script.find("#SBATCH --array=0-2\n"), std::string::npos) << script;
  EXPECT_NE(script.find("#SBATCH --time=00:10:00\n"), std::string::npos);
  EXPECT_NE(script.find("#SBATCH --partition=debug\n"), std::string::npos);
  EXPECT_NE(script.find("--shard \"$shard/3\""), std::string::npos);
  EXPECT_TRUE(fs::is_directory(dir + "/out/logs"));
  EXPECT_FALSE(fs::exists(dir + "/out/results.jsonl"));  // nothing ran

  // A line break in an option wrote a shell command of its own into the script (hostile pass).
  const auto injected = runParksim("sweep " + dir + "/spec.yaml --out " + dir +
                                   "/injected --slurm --slurm-partition \"debug\necho INJECTED\"");
  EXPECT_EQ(injected.exit_code, 2) << injected.out;
  EXPECT_NE(injected.out.find("--slurm-partition: must be one word"), std::string::npos)
      << injected.out;
  EXPECT_FALSE(fs::exists(dir + "/injected"));
  // Paths reach the terminal escaped, as plan's and run's do (they were echoed raw).
  const auto escaped =
      runParksim("sweep " + dir + "/spec.yaml --out \"" + dir + "/red\x1b[31m\" --shard 0/5");
  EXPECT_EQ(escaped.exit_code, 0) << escaped.out;
  EXPECT_EQ(escaped.out.find('\x1b'), std::string::npos) << escaped.out;
  EXPECT_NE(escaped.out.find("red\\x1B[31m"), std::string::npos) << escaped.out;
}

// Issue 22: an offset that moves the robot out of the lot is named by its line in the spec.
TEST(SweepCli, ABadOffsetIsNamedByItsLineInTheSpec) {
  const std::string dir = scratchDir();
  writeText(dir + "/spec.yaml",
            studySpec("planners: rrt\nstart_offsets:\n  - [0, 0, 0]\n  - [100, 0, 0]\n"));
  const auto r = runParksim("sweep " + dir + "/spec.yaml --out " + dir + "/out");
  EXPECT_EQ(r.exit_code, 2) << r.out;
  EXPECT_NE(r.out.find(dir + "/spec.yaml:7: start_offsets[1]: start offset on head_in: "),
            std::string::npos)
      << r.out;
  EXPECT_FALSE(fs::exists(dir + "/out"));
}

// Issue 22: a byte changed in a results row is found by merge, report and verify, each naming
// the file and the line; verify passes the intact table.
TEST(SweepCli, AChangedRowIsReportedByMergeReportAndVerify) {
  const std::string dir = scratchDir();
  writeText(dir + "/spec.yaml", studySpec("planners: rrt-goal-connect\nseeds: [1, 2, 3]\n"));
  const std::string out = dir + "/out";
  const auto swept = runParksim("sweep " + dir + "/spec.yaml --out " + out);
  ASSERT_LE(swept.exit_code, 1) << swept.out;
  const auto intact = runParksim("verify " + out);
  EXPECT_EQ(intact.exit_code, 0) << intact.out;
  EXPECT_NE(intact.out.find("3 rows intact, 0 problems"), std::string::npos) << intact.out;

  // One digit of the second row's seed changed, as a bad disk or a careless edit would.
  const std::string jsonl = out + "/results.jsonl";
  std::string text = slurp(jsonl);
  const std::size_t second = text.find('\n') + 1;
  const std::size_t digit = text.find("\"seed\":", second) + 7;
  text[digit] = text[digit] == '7' ? '8' : '7';
  writeText(jsonl, text);
  const std::string where = jsonl + ":2: row_checksum ";
  const auto merged = runParksim("merge " + out + " --out " + dir + "/merged");
  EXPECT_EQ(merged.exit_code, 2) << merged.out;
  EXPECT_NE(merged.out.find(where), std::string::npos) << merged.out;
  EXPECT_FALSE(fs::exists(dir + "/merged/results.jsonl"));
  const auto reported = runParksim("report " + out);
  EXPECT_EQ(reported.exit_code, 2) << reported.out;
  EXPECT_NE(reported.out.find(where), std::string::npos) << reported.out;
  const auto verified = runParksim("verify " + out);
  EXPECT_EQ(verified.exit_code, 1) << verified.out;
  EXPECT_NE(verified.out.find(where), std::string::npos) << verified.out;
  EXPECT_NE(verified.out.find("2 rows intact, 1 problem"), std::string::npos) << verified.out;
  const auto resumed = runParksim("sweep " + dir + "/spec.yaml --out " + out);
  EXPECT_EQ(resumed.exit_code, 2) << resumed.out;
  EXPECT_NE(resumed.out.find(where), std::string::npos) << resumed.out;
}

// --slurm --missing writes the script again: it asks for what the first --slurm asked (not the
// defaults: 1G could be less memory than the episodes need), except what its own options name.
// A stand-in sbatch on PATH records its arguments.
TEST(SweepCli, MissingAsksForTheFirstSubmissionsResources) {
  const std::string dir = scratchDir();
  writeText(dir + "/spec.yaml", studySpec("seeds: {from: 1, to: 4}\n"));
  fs::create_directories(dir + "/bin");
  writeText(dir + "/bin/sbatch",
            "#!/bin/sh\necho \"$@\" >> \"$(dirname \"$0\")/calls\"\necho 42\n");
  fs::permissions(dir + "/bin/sbatch", fs::perms::owner_all);
  const std::string parksim = "PATH=" + dir + "/bin:$PATH " + testing::parksimExe();
  const std::string sweep = "sweep " + dir + "/spec.yaml --out " + dir + "/out --slurm";
  ASSERT_EQ(runParksim(sweep + " --slurm-shards 2 --slurm-mem 300M --slurm-time 00:07:00 "
                               "--slurm-max-parallel 1")
                .exit_code,
            0);
  // No shard ran: both are missing.
  const auto again = testing::runProgram(parksim, sweep + " --missing");
  ASSERT_EQ(again.exit_code, 0) << again.out;
  EXPECT_NE(again.out.find("submitted job 42: array tasks 0,1 of 2"), std::string::npos)
      << again.out;
  std::string script = slurp(dir + "/out/sweep.sbatch");
  EXPECT_NE(script.find("#SBATCH --mem=300M\n"), std::string::npos) << script;
  EXPECT_NE(script.find("#SBATCH --time=00:07:00\n"), std::string::npos) << script;
  EXPECT_NE(script.find("#SBATCH --array=0-1%1\n"), std::string::npos) << script;
  // A longer time limit for the resubmission; the memory stays the first submission's.
  const auto longer = testing::runProgram(parksim, sweep + " --missing --slurm-time 00:20:00");
  ASSERT_EQ(longer.exit_code, 0) << longer.out;
  script = slurp(dir + "/out/sweep.sbatch");
  EXPECT_NE(script.find("#SBATCH --time=00:20:00\n"), std::string::npos) << script;
  EXPECT_NE(script.find("#SBATCH --mem=300M\n"), std::string::npos) << script;
  // An edited sweep.json cannot change the array's range through the throttle.
  std::string manifest = slurp(dir + "/out/sweep.json");
  const std::size_t at = manifest.find("\"max_parallel\": \"%1\"");
  ASSERT_NE(at, std::string::npos) << manifest;
  writeText(dir + "/out/sweep.json", manifest.replace(at, 20, "\"max_parallel\": \"0-5\""));
  const auto edited = testing::runProgram(parksim, sweep + " --missing");
  EXPECT_EQ(edited.exit_code, 2) << edited.out;
  // The file and the field are named; the option that overrides the field mends it.
  EXPECT_NE(edited.out.find(dir + "/out/sweep.json: slurm_request.max_parallel "
                                  "(--slurm-max-parallel overrides it): the array's throttle "
                                  "must be %K with K from 1 to 100000, got 0-5"),
            std::string::npos)
      << edited.out;
  const auto mended = testing::runProgram(parksim, sweep + " --missing --slurm-max-parallel 2");
  EXPECT_EQ(mended.exit_code, 0) << mended.out;
  EXPECT_NE(slurp(dir + "/out/sweep.sbatch").find("#SBATCH --array=0-1%2\n"), std::string::npos);
  const std::string calls = slurp(dir + "/bin/calls");
  // The throttle of the first submission too: --array on the command line replaces the script's.
  EXPECT_NE(calls.find("--parsable --array=0,1%1 " + dir + "/out/sweep.sbatch"), std::string::npos)
      << calls;
}

TEST(SweepCli, MissingNeedsASlurmSweep) {
  const std::string dir = scratchDir();
  writeText(dir + "/spec.yaml", studySpec("seeds: [1, 2]\n"));
  const auto plain = runParksim("sweep " + dir + "/spec.yaml --out " + dir + "/out --missing");
  EXPECT_EQ(plain.exit_code, 2) << plain.out;
  EXPECT_NE(plain.out.find("--missing works on a Slurm sweep: add --slurm"), std::string::npos);
  const auto none =
      runParksim("sweep " + dir + "/spec.yaml --out " + dir + "/out --slurm --missing");
  EXPECT_EQ(none.exit_code, 2) << none.out;
  EXPECT_NE(none.out.find("/out/sweep.json: no Slurm sweep here"), std::string::npos) << none.out;
}

// The cheapest whole episode (bench/scale/tiny.yaml: 3 ms), with `axes`.
std::string tinySpec(const std::string& axes) {
  return "format: parksim-sweep/1\nname: tiny\nworlds: [" + testing::sourceDir() +
         "/bench/scale/tiny.yaml]\nplanners: hybrid-a-star\ntracking: open\n" + axes;
}

// The rows of a table by id, timing and provenance aside: what must not depend on how the
// episodes were run.
std::map<std::string, nlohmann::json> rowsById(const std::string& jsonl) {
  std::map<std::string, nlohmann::json> rows;
  std::size_t start = 0;
  const std::string text = slurp(jsonl);
  while (start < text.size()) {
    const std::size_t nl = text.find('\n', start);
    nlohmann::json row = nlohmann::json::parse(text.substr(start, nl - start));
    for (const char* key : {"plan_time_s", "plan_first_solution_s", "sim_wall_s", "episode_wall_s",
                            "plan_cost_history", "plan_phase_times_s", "row_checksum", "host"}) {
      row.erase(key);
    }
    rows[row["episode_id"].get<std::string>()] = row;
    start = nl + 1;
  }
  return rows;
}

// The example: two values of a robot limit, two episodes per other combination, each
// value in its column, every id different; a bad path or value refused with the spec's line.
TEST(SweepCli, SetAxesAreColumnsAndPartOfTheIds) {
  const std::string dir = scratchDir();
  writeText(dir + "/spec.yaml",
            tinySpec("seeds: [1, 2]\nset: {robot.max_wheel_speed_radps: [6, 10]}\n"));
  const auto r = runParksim("sweep " + dir + "/spec.yaml --out " + dir + "/out --workers 2");
  EXPECT_EQ(r.exit_code, 0) << r.out;
  const std::map<std::string, nlohmann::json> rows = rowsById(dir + "/out/results.jsonl");
  ASSERT_EQ(rows.size(), 4u);
  std::map<double, int> per_value;
  for (const auto& [id, row] : rows) ++per_value[row["robot.max_wheel_speed_radps"].get<double>()];
  EXPECT_EQ(per_value, (std::map<double, int>{{6.0, 2}, {10.0, 2}}));
  const std::string header = slurp(dir + "/out/results.csv").substr(0, 400);
  EXPECT_NE(header.find(",sample,robot.max_wheel_speed_radps,status,"), std::string::npos)
      << header;
  for (const char* axes : {"set:\n  robot.max_wheel_speed_radps: [6, -10]\n",
                           "set:\n  robot.max_wheel_speed: [6]\n"}) {
    writeText(dir + "/bad.yaml", tinySpec(axes));
    const auto bad = runParksim("sweep " + dir + "/bad.yaml --out " + dir + "/bad");
    EXPECT_EQ(bad.exit_code, 2) << bad.out;
    EXPECT_NE(bad.out.find("bad.yaml:7: set: robot.max_wheel_speed"), std::string::npos) << bad.out;
    EXPECT_FALSE(fs::exists(dir + "/bad"));
  }
}

// samples: {count: 20, seed: 1}: the same 20 episodes, values and ids, twice, in one process,
// sharded two ways, and resumed after a kill.
TEST(SweepCli, ASampledSpecGivesTheSameEpisodesHoweverItRuns) {
  const std::string dir = scratchDir();
  writeText(dir + "/spec.yaml", tinySpec("set:\n  robot.max_wheel_speed_radps: {uniform: [6, 12]}\n"
                                         "  goal.position_tolerance: {normal: [0.003, 0.0003]}\n"
                                         "samples: {count: 20, seed: 1}\n"));
  const std::string spec = dir + "/spec.yaml";
  const auto list = runParksim("sweep " + spec + " --list");
  EXPECT_EQ(list.exit_code, 0);
  EXPECT_EQ(list.out, runParksim("sweep " + spec + " --list").out);
  EXPECT_EQ(std::count(list.out.begin(), list.out.end(), '\n'), 20);

  EXPECT_EQ(runParksim("sweep " + spec + " --out " + dir + "/one --workers 1").exit_code, 0);
  const std::map<std::string, nlohmann::json> one = rowsById(dir + "/one/results.jsonl");
  ASSERT_EQ(one.size(), 20u);
  for (const auto& [id, row] : one) {
    EXPECT_NE(list.out.find(id), std::string::npos) << id;
    EXPECT_TRUE(row["sample"].is_number()) << id;
  }
  // Sharded two ways, then merged.
  for (int i = 0; i < 2; ++i) {
    const std::string shard = std::to_string(i) + "/2";
    EXPECT_EQ(runParksim("sweep " + spec + " --shard " + shard + " --out " + dir +
                         "/sharded/shards/" + std::to_string(i))
                  .exit_code,
              0);
  }
  EXPECT_EQ(runParksim("merge " + dir + "/sharded").exit_code, 0);
  EXPECT_EQ(rowsById(dir + "/sharded/results.jsonl"), one);
  // Killed after its first rows and resumed.
  const std::string out = dir + "/killed";
  sweepThenKill(spec, out, 3);
  EXPECT_EQ(runParksim("sweep " + spec + " --out " + out).exit_code, 0);
  EXPECT_EQ(rowsById(out + "/results.jsonl"), one);
}

}  // namespace
}  // namespace parksim
