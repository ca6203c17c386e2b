// Runs small real sweeps (head-in world, goal-connect RRT: ~0.1 s per episode) through the
// library: worker counts, resuming after a kill, shards and merging.

#include "parksim/sweep/run/SweepRunner.h"

#include <filesystem>
#include <fstream>
#include <map>
#include <set>

#include <sys/stat.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include "parksim/core/io/Error.h"
#include "parksim/results/episode/ExecutedFile.h"
#include "parksim/results/tables/RowSeal.h"
#include "parksim/sweep/shards/Merge.h"
#include "parksim/sweep/shards/Shard.h"
#include "parksim/sweep/shards/SweepManifest.h"
#include "parksim/sweep/spec/SweepSpecReader.h"
#include "tests/support/TestPaths.h"
#include "tests/sweep/SweepTestSupport.h"

namespace parksim {
namespace {

using Json = nlohmann::ordered_json;
using testing::scratchDir;
using testing::studySpec;

struct SmallSweep {
  SweepSpec spec;
  std::vector<SweepWorld> worlds;
  std::vector<SweepEpisode> episodes;

  explicit SmallSweep(const std::string& axes)
      : spec(parseSweepSpec(studySpec(axes), "spec.yaml", "")),
        worlds(loadSweepWorlds(spec)),
        episodes(expandEpisodes(spec, worlds)) {}
};

// Three seeds of the goal-connect RRT; the suite's reference adds a 1-iteration budget (which
// fails to plan) so that the table holds failures too.
const char* kAxes = "planners: rrt-goal-connect\nseeds: [1, 2, 3]\ntracking: closed\n";

SweepProgress run(const std::vector<SweepEpisode>& episodes, const std::string& dir, int workers,
                  const SweepRecordDef& record = {}, bool processes = false) {
  ResultsTable table(dir);
  SweepRunnerDef def;
  def.workers = workers;
  def.processes = processes;
  def.episode.record = record;
  def.episode.episodes_dir = dir + "/episodes";
  return runSweep(episodes, def, table);
}

// Rows by id, timing keys removed: what must not depend on how the sweep ran.
std::map<std::string, Json> content(const std::vector<Json>& rows) {
  std::map<std::string, Json> out;
  for (const Json& row : rows) {
    const std::string id = row.at("episode_id").get<std::string>();
    EXPECT_TRUE(out.emplace(id, withoutTiming(row)).second) << "duplicate " << id;
  }
  return out;
}

std::map<std::string, Json> tableContent(const std::string& dir) {
  return content(readResultsJsonl(dir + "/results.jsonl"));
}

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

std::size_t lineCount(const std::string& path) {
  const std::string text = slurp(path);
  return static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n'));
}

class SweepRunnerTest : public ::testing::Test {
 protected:
  // The reference: one worker, run once per test binary.
  static void SetUpTestSuite() {
    sweep_ = new SmallSweep(std::string(kAxes) + "max_iterations: [1, 2000]\n");
    // One per process: ctest runs each test of this suite as its own process, in parallel.
    reference_dir_ = new std::string(parksim::testing::binaryDir() + "/test-out/sweep/reference-" +
                                     std::to_string(getpid()));
    std::filesystem::remove_all(*reference_dir_);
    run(sweep_->episodes, *reference_dir_, 1);
  }
  static void TearDownTestSuite() {
    delete sweep_;
    std::filesystem::remove_all(*reference_dir_);
    delete reference_dir_;
  }
  static SmallSweep* sweep_;
  static std::string* reference_dir_;
};

SmallSweep* SweepRunnerTest::sweep_ = nullptr;
std::string* SweepRunnerTest::reference_dir_ = nullptr;

TEST_F(SweepRunnerTest, WritesOneWholeRowPerEpisodeToBothFiles) {
  const std::map<std::string, Json> rows = tableContent(*reference_dir_);
  ASSERT_EQ(rows.size(), sweep_->episodes.size());
  EXPECT_EQ(lineCount(*reference_dir_ + "/results.csv"), rows.size() + 1);
  int plan_failed = 0;
  for (const auto& [id, row] : rows) {
    EXPECT_EQ(row.at("parksim_version").get<std::string>().empty(), false);
    EXPECT_TRUE(row.at("bullet_precision") == "float" || row.at("bullet_precision") == "double");
    if (row.at("status") == "plan_failed") {
      ++plan_failed;
      EXPECT_FALSE(row.at("met_tolerance").get<bool>());
      EXPECT_FALSE(row.contains("max_pos_err_m"));  // nothing was simulated
      EXPECT_EQ(row.at("max_iterations"), 1);
    } else {
      // Every solved plan tracks within the default tolerance on the study world (README).
      EXPECT_TRUE(row.at("met_tolerance").get<bool>()) << row.at("failure");
      EXPECT_LT(row.at("max_pos_err_m").get<double>(), 0.005);
    }
  }
  // One iteration rarely parks the study's robot; 2000 always do for these seeds.
  EXPECT_GE(plan_failed, 1);
}

TEST_F(SweepRunnerTest, TwoWorkersWriteTheSameTableAsOne) {
  const std::string dir = scratchDir();
  const SweepProgress p = run(sweep_->episodes, dir, 2);
  EXPECT_EQ(p.ran, sweep_->episodes.size());
  EXPECT_EQ(tableContent(dir), tableContent(*reference_dir_));
}

// Workers that are processes (as for user code) send rows back as JSON text: the same rows,
// to the bit, as threads make.
TEST_F(SweepRunnerTest, WorkerProcessesWriteTheSameTableAsThreads) {
  const std::string dir = scratchDir();
  const SweepProgress p = run(sweep_->episodes, dir, 2, {}, true);
  EXPECT_EQ(p.ran, sweep_->episodes.size());
  EXPECT_EQ(tableContent(dir), tableContent(*reference_dir_));
}

TEST_F(SweepRunnerTest, ResumesAfterAKillRunningOnlyTheMissingEpisodes) {
  const std::string dir = scratchDir();
  std::filesystem::copy(*reference_dir_ + "/results.jsonl", dir + "/results.jsonl");
  std::filesystem::copy(*reference_dir_ + "/results.csv", dir + "/results.csv");
  // What a kill in the middle of the third row's write could leave: two whole rows and part of
  // the third in results.jsonl, one whole row in results.csv.
  const std::string jsonl = slurp(dir + "/results.jsonl");
  std::size_t cut = 0;
  for (int i = 0; i < 2; ++i) cut = jsonl.find('\n', cut) + 1;
  std::filesystem::resize_file(dir + "/results.jsonl", cut + 40);
  const std::string csv = slurp(dir + "/results.csv");
  std::filesystem::resize_file(dir + "/results.csv", csv.find('\n', csv.find('\n') + 1) + 1);

  const SweepProgress p = run(sweep_->episodes, dir, 2);
  EXPECT_EQ(p.ran, sweep_->episodes.size() - 2);
  EXPECT_EQ(tableContent(dir), tableContent(*reference_dir_));
  EXPECT_EQ(lineCount(dir + "/results.csv"), sweep_->episodes.size() + 1);
  // And once complete, the same command runs nothing.
  EXPECT_EQ(run(sweep_->episodes, dir, 2).ran, 0u);
  EXPECT_EQ(lineCount(dir + "/results.jsonl"), sweep_->episodes.size());
}

TEST_F(SweepRunnerTest, ThreeShardsMergedEqualTheWholeSweep) {
  const std::string dir = scratchDir();
  std::vector<std::string> shard_dirs;
  std::size_t total = 0;
  for (int i = 0; i < 3; ++i) {
    const std::vector<SweepEpisode> part = selectShard(sweep_->episodes, Shard{i, 3});
    EXPECT_GE(part.size(), 2u);  // 6 episodes: two per shard
    total += part.size();
    shard_dirs.push_back(dir + "/shards/" + std::to_string(i));
    run(part, shard_dirs.back(), 1);
  }
  EXPECT_EQ(total, sweep_->episodes.size());
  const MergeResult merged = mergeResults(mergeSources(dir));
  EXPECT_TRUE(merged.duplicated.empty());
  EXPECT_TRUE(merged.conflicting.empty());
  EXPECT_TRUE(merged.mixes.empty());
  EXPECT_EQ(content(mergedRows(merged)), tableContent(*reference_dir_));
  EXPECT_TRUE(std::is_sorted(merged.rows.begin(), merged.rows.end(),
                             [](const MergedRow& a, const MergedRow& b) { return a.id < b.id; }));

  // Idempotent: merging the merged table with its sources again changes nothing and reports
  // every episode as duplicated, none as conflicting.
  writeMergedTable(dir, merged);
  std::vector<std::string> again = shard_dirs;
  again.push_back(dir);
  const MergeResult twice = mergeResults(again);
  EXPECT_EQ(content(mergedRows(twice)), content(mergedRows(merged)));
  EXPECT_EQ(twice.duplicated.size(), merged.rows.size());
  EXPECT_TRUE(twice.conflicting.empty());
}

TEST(Shard, EveryEpisodeInExactlyOneShardOfBalancedSize) {
  std::vector<SweepEpisode> all(23);
  for (std::size_t i = 0; i < all.size(); ++i) all[i].id = std::to_string(100 + i);
  std::set<std::string> seen;
  for (int i = 0; i < 4; ++i) {
    const std::vector<SweepEpisode> part = selectShard(all, Shard{i, 4});
    EXPECT_TRUE(part.size() == 5 || part.size() == 6);
    for (const SweepEpisode& e : part) EXPECT_TRUE(seen.insert(e.id).second);
  }
  EXPECT_EQ(seen.size(), all.size());
  EXPECT_THROW(parseShard("4/4"), Error);
  EXPECT_THROW(parseShard("1/0"), Error);
  EXPECT_THROW(parseShard("1/2x"), Error);
  EXPECT_EQ(parseShard("3/8").index, 3);
}

TEST(MergeResults, ListsMissingEpisodesFromTheManifest) {
  const std::string dir = scratchDir();
  const SmallSweep sweep(kAxes);
  SweepManifest manifest{"spec.yaml", "test", Shard{0, 2}, {}};
  for (const SweepEpisode& e : sweep.episodes) manifest.episode_ids.push_back(e.id);
  writeSweepManifest(dir + "/shards/0", manifest);
  run(selectShard(sweep.episodes, Shard{0, 2}), dir + "/shards/0", 1);
  const MergeResult r = mergeResults(mergeSources(dir));
  const std::vector<SweepEpisode> other = selectShard(sweep.episodes, Shard{1, 2});
  EXPECT_EQ(r.expected, sweep.episodes.size());
  ASSERT_EQ(r.missing.size(), other.size());
  for (const SweepEpisode& e : other) {
    EXPECT_NE(std::find(r.missing.begin(), r.missing.end(), e.id), r.missing.end());
  }
}

TEST(EpisodeRecording, ExecutedCsvAndFilmOfFailuresAtTheChosenRates) {
  const std::string dir = scratchDir();
  // Closed loop meets the default tolerance; with a 0.1 um bound on the tracking error it fails.
  const SmallSweep sweep("seeds: [1]\ntracking: [closed]\ntolerance: {max_pos_err_m: 1e-7}\n");
  SweepRecordDef record;
  record.executed_csv = FilesPolicy::kFailures;
  record.executed_rate_hz = 10.0;
  record.film_failures = true;
  record.film_fps = 1.0;  // few, small frames: the test checks that the failure is filmed
  record.film_width_px = 64;
  record.film_height_px = 48;
  SweepRunnerDef def;
  ResultsTable table(dir);
  def.episode.record = record;
  def.episode.episodes_dir = dir + "/episodes";
  runSweep(sweep.episodes, def, table);
  const std::vector<Json> rows = readResultsJsonl(dir + "/results.jsonl");
  ASSERT_EQ(rows.size(), 1u);
  EXPECT_EQ(rows[0]["status"], "tolerance_missed");
  // A sweep records executed.npz by default (SweepRecordDef::format), not executed.csv.
  const std::string episode = dir + "/episodes/" + sweep.episodes[0].id;
  EXPECT_FALSE(std::filesystem::exists(episode + "/executed.csv"));
  const std::vector<DataColumn> columns = readRecordFile(episode + "/executed.npz");
  ASSERT_FALSE(columns.empty());
  // 10 rows per simulated second (every 24th step at 240 Hz), plus the last row.
  const double sim_time_s = rows[0]["sim_time_s"].get<double>();
  const double rows_written = static_cast<double>(columns[0].values.size());
  EXPECT_NEAR(rows_written, std::floor(sim_time_s * 10.0) + 2.0, 1.0);
  // Filmed: one frame per simulated second from t = 0, and the final instant.
  const std::string frames = dir + "/episodes/" + sweep.episodes[0].id + "/frames";
  ASSERT_TRUE(std::filesystem::is_directory(frames));
  const auto n = std::distance(std::filesystem::directory_iterator(frames),
                               std::filesystem::directory_iterator());
  EXPECT_NEAR(static_cast<double>(n), std::floor(sim_time_s) + 2.0, 1.0);
}

TEST(ResultsTableFile, RejectsATableWithOtherColumns) {
  const std::string dir = scratchDir();
  testing::writeText(dir + "/results.csv", "episode_id,something_else\n");
  EXPECT_THROW(ResultsTable table(dir), Error);
}

// A row with a key of the wrong type (a hand edit, another tool) was a JSON type error in
// sweep, merge and report, exit 3 (hostile pass); it is refused naming the line and the key.
TEST(ResultsTableFile, RefusesRowsWithKeysOfTheWrongType) {
  const std::string dir = scratchDir();
  // Sealed, so that the seal is not what is wrong with them.
  std::string text;
  for (const char* r : {R"({"episode_id": "a", "met_tolerance": true})",
                        R"({"episode_id": "b", "met_tolerance": "yes"})",
                        R"({"episode_id": "c", "met_tolerance": false})"}) {
    text += sealRow(Json::parse(r)).line + "\n";
  }
  testing::writeText(dir + "/results.jsonl", text);
  try {
    readResultsJsonl(dir + "/results.jsonl");
    ADD_FAILURE() << "accepted";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()),
              dir + "/results.jsonl:2: key 'met_tolerance' must be true or false, got \"yes\"");
  }
  EXPECT_THROW(ResultsTable table(dir), Error);
}

// A results.jsonl that is a device or a FIFO was read until 2 GB (report, merge; sweep then
// exited 3) or forever (hostile pass); it is refused like any input file that is not regular.
TEST(ResultsTableFile, RefusesADeviceOrFifoAsTheTable) {
  const std::string dir = scratchDir();
  std::filesystem::create_symlink("/dev/zero", dir + "/results.jsonl");
  const auto message = [](const auto& f) {
    try {
      f();
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  const std::string expected = dir + "/results.jsonl: is not a regular file";
  EXPECT_EQ(message([&] { readResultsJsonl(dir + "/results.jsonl"); }).rfind(expected, 0), 0u);
  EXPECT_EQ(message([&] { ResultsTable table(dir); }).rfind(expected, 0), 0u);
  std::filesystem::remove(dir + "/results.jsonl");
  ASSERT_EQ(::mkfifo((dir + "/results.jsonl").c_str(), 0600), 0);
  EXPECT_EQ(message([&] { readResultsJsonl(dir + "/results.jsonl"); }).rfind(expected, 0), 0u);
  // sweep.json likewise (a FIFO blocked its open); a key of the wrong type was a JSON type
  // error, exit 3.
  SweepManifest m;
  ASSERT_EQ(::mkfifo((dir + "/sweep.json").c_str(), 0600), 0);
  EXPECT_EQ(
      message([&] { readSweepManifest(dir, m); }).rfind(dir + "/sweep.json: is not a regular", 0),
      0u);
  std::filesystem::remove(dir + "/sweep.json");
  testing::writeText(dir + "/sweep.json",
                     "{\"format\": \"parksim-sweep-manifest/2\", \"episode_id_format\": 3, "
                     "\"name\": 5, \"episode_ids\": []}");
  EXPECT_EQ(message([&] { readSweepManifest(dir, m); }),
            dir + "/sweep.json: not a sweep manifest (format parksim-sweep-manifest/2)");
}

// A table written by parksim 0.2 holds ids of another format (defaults left out, other
// defaults): it is refused by name, not resumed into a mix of two meanings of one id.
TEST(SweepManifestFile, RefusesATableOfAnotherEpisodeIdFormat) {
  const std::string dir = scratchDir();
  testing::writeText(dir + "/sweep.json",
                     "{\"format\": \"parksim-sweep-manifest/1\", \"spec\": \"s.yaml\", "
                     "\"name\": \"old\", \"shard\": \"0/1\", \"episode_ids\": []}");
  SweepManifest m;
  std::string why;
  try {
    readSweepManifest(dir, m);
  } catch (const Error& e) {
    why = e.what();
  }
  EXPECT_NE(why.find("written by parksim 0.2"), std::string::npos) << why;
  EXPECT_NE(why.find("sweep into a new --out"), std::string::npos) << why;
  // What this version writes, it reads back, with its id format.
  const SweepManifest written{"spec.yaml", "now", Shard{1, 3}, {"00000000000000aa"}};
  writeSweepManifest(dir, written);
  ASSERT_TRUE(readSweepManifest(dir, m));
  EXPECT_EQ(m.episode_ids, written.episode_ids);
  EXPECT_EQ(m.shard.index, 1);
  EXPECT_NE(slurp(dir + "/sweep.json").find("\"episode_id_format\": 3"), std::string::npos);
  // A table of format 2 (before the set: axes) is refused by name too.
  testing::writeText(dir + "/sweep.json",
                     "{\"format\": \"parksim-sweep-manifest/2\", \"episode_id_format\": 2, "
                     "\"episode_ids\": []}");
  why.clear();
  try {
    readSweepManifest(dir, m);
  } catch (const Error& e) {
    why = e.what();
  }
  EXPECT_NE(why.find("episode ids (format 2) hash other text"), std::string::npos) << why;
}

}  // namespace
}  // namespace parksim
