// Every file parksim writes and reads, inside a host program that switched to a decimal-comma
// locale (de_DE.UTF-8, both the C locale and the global C++ locale): the files must be
// byte-identical to the C locale's and read back to exactly the values written.

#include <clocale>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <locale>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "bench/planning/BenchCsv.h"
#include "parksim/collision/BulletCollisionWorld.h"
#include "parksim/core/io/Csv.h"
#include "parksim/core/io/NumberFormat.h"
#include "parksim/core/model/Trajectory.h"
#include "parksim/pipeline/Verdict.h"
#include "parksim/renders/plots/TrackingPlot.h"
#include "parksim/results/episode/ExecutedFile.h"
#include "parksim/results/episode/JsonFile.h"
#include "parksim/results/episode/MetricsFile.h"
#include "parksim/results/episode/PlanFile.h"
#include "parksim/results/episode/TrajectoryFile.h"
#include "parksim/scenario/world/ScenarioReader.h"
#include "tests/support/TestPaths.h"

namespace parksim {
namespace {

namespace fs = std::filesystem;

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

constexpr const char* kDecimalComma = "de_DE.UTF-8";

// Everything a run writes, produced under the current locale into `dir`.
struct Written {
  Scenario scenario;
  PlanSetup setup;
  PlanResult plan;
  EpisodeResult episode;
  nlohmann::json metrics;
  std::string bench_csv;
};

Written writeEverything(const fs::path& dir) {
  Written w{
      loadScenario(parksim::testing::sourceDir() + "/worlds/head_in.yaml"), {}, {}, {}, {}, {}};
  w.setup.search.seed = 1;
  const BulletCollisionWorld collision(w.scenario);
  w.plan = planScenario(w.scenario, collision, w.setup);
  writePlanFiles(dir.string(), w.scenario, &w.plan.trajectory,
                 planSummary(w.scenario, w.setup, w.plan));
  w.episode = runEpisode(w.scenario, w.plan.trajectory);
  writeExecutedCsv((dir / "executed.csv").string(), w.episode.rows);
  w.metrics = metricsToJson(w.episode.metrics);
  writeJsonFile((dir / "metrics.json").string(), w.metrics);
  bench::BenchRecord r;
  r.library = "parksim";
  r.planner = "rrt";
  r.space = "move-to-pose";
  r.scenario = "head_in";
  r.seed = 3;
  r.budget = "time=0.1s";
  r.solved = r.valid = true;
  r.status = "solved";
  r.time_first_s = 0.000123;
  r.time_total_s = 0.25;
  r.length_m = 1.5;
  r.min_clearance_m = 0.0042;
  r.phases_s = {{"sampling", 1.25e-5}};
  w.bench_csv = bench::benchCsv({r});
  return w;
}

class LocaleRoundTrip : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::path(parksim::testing::binaryDir()) / "test-output" / "locale";
    fs::remove_all(dir_);
    fs::create_directories(dir_ / "c");
    fs::create_directories(dir_ / "de");
  }
  void TearDown() override {
    std::locale::global(std::locale::classic());
    std::setlocale(LC_ALL, "C");
  }
  fs::path dir_;
};

TEST_F(LocaleRoundTrip, EveryFileIsTheSameAndReadsBackUnderADecimalCommaLocale) {
  const Written c = writeEverything(dir_ / "c");

  if (std::setlocale(LC_ALL, kDecimalComma) == nullptr) {
    GTEST_SKIP() << "locale " << kDecimalComma
                 << " is not installed (scripts/install-deps.sh generates it with localedef)";
  }
  std::locale::global(std::locale(kDecimalComma));
  // The locale really is in effect: printf now writes a decimal comma.
  char probe[16];
  std::snprintf(probe, sizeof probe, "%.1f", 0.5);
  ASSERT_EQ(std::string(probe), "0,5");

  const fs::path de = dir_ / "de";
  const Written w = writeEverything(de);
  ASSERT_TRUE(w.plan.solved());

  // trajectory.csv and executed.csv: the same bytes as in the C locale, exact values back.
  EXPECT_EQ(slurp(de / "trajectory.csv"), slurp(dir_ / "c" / "trajectory.csv"));
  EXPECT_EQ(slurp(de / "executed.csv"), slurp(dir_ / "c" / "executed.csv"));
  EXPECT_EQ(readTrajectoryCsv((de / "trajectory.csv").string()), w.plan.trajectory);
  const CsvTable executed = readCsvFile((de / "executed.csv").string());
  ASSERT_EQ(executed.rows().size(), w.episode.rows.size());
  for (std::size_t i = 0; i < executed.rows().size(); ++i) {
    const ExecutedRow& r = w.episode.rows[i];
    const CsvTable::Row& row = executed.rows()[i];
    ASSERT_EQ(executed.number(row, executed.column("t")), r.t_s);
    ASSERT_EQ(executed.number(row, executed.column("x")), r.pose.x);
    ASSERT_EQ(executed.number(row, executed.column("theta_ref")), r.reference.theta);
    ASSERT_EQ(executed.number(row, executed.column("omega_left_cmd")), r.wheels_cmd.left_radps);
    ASSERT_EQ(executed.number(row, executed.column("pos_err")), r.pos_err_m);
  }
  const TrackingSeries series = readTrackingCsv((de / "executed.csv").string());
  ASSERT_EQ(series.t_s.size(), w.episode.rows.size());
  EXPECT_EQ(series.heading_error_rad.back(), w.episode.rows.back().heading_err_rad);

  // plan.json and metrics.json: parse back to exactly the objects written.
  const nlohmann::json plan = readJsonFile((de / "plan.json").string());
  EXPECT_EQ(plan, planSummary(w.scenario, w.setup, w.plan));
  EXPECT_EQ(plan["path_length_m"].get<double>(), w.plan.trajectory.pathLength(w.scenario.robot));
  const nlohmann::json metrics = readJsonFile((de / "metrics.json").string());
  EXPECT_EQ(metrics, w.metrics);
  EXPECT_EQ(metricsFromJson(metrics).max_pos_err_m, w.episode.metrics.max_pos_err_m);
  EXPECT_TRUE(checkTrackingFile({}, (de / "metrics.json").string()).empty());

  // bench.csv: same text, numbers read back.
  EXPECT_EQ(w.bench_csv, c.bench_csv);
  const CsvTable bench(w.bench_csv, "bench.csv");
  EXPECT_EQ(bench.number(bench.rows()[0], bench.column("time_first_s")), 0.000123);
  EXPECT_EQ(bench.number(bench.rows()[0], bench.column("min_clearance_m")), 0.0042);
  EXPECT_EQ(bench.number(bench.rows()[0], bench.column("phase_sampling_s")), 1.25e-5);
  EXPECT_EQ(bench.cell(bench.rows()[0], bench.column("budget")), "time=0.1s");

  // Labels and messages.
  EXPECT_EQ(formatTick(0.5, 0.1), "0.5");
  EpisodeMetrics m;
  m.max_pos_err_m = 0.0061;
  EXPECT_EQ(checkTracking({}, m).front(), "max_pos_err_m 0.0061 > 0.005");
}

}  // namespace
}  // namespace parksim
