// The executed record: executed.csv's header and exact numbers; executed.npz with the same
// columns, exact, at most a third of the CSV's bytes for a 240 Hz episode (issue 20).

#include "parksim/results/episode/ExecutedFile.h"

#include <bit>
#include <filesystem>
#include <memory>
#include <sstream>

#include <gtest/gtest.h>

#include "parksim/core/io/Error.h"
#include "parksim/pipeline/EpisodePipeline.h"
#include "tests/support/RunParksim.h"
#include "tests/support/TestPaths.h"

namespace parksim {
namespace {

TEST(ExecutedFile, ExecutedCsvHeaderAndRoundTripPrecision) {
  ExecutedRow row;
  row.t_s = 1.0 / 240.0;
  row.pose = {0.1, 1.0 / 3.0, -2.0 / 7.0};
  row.pos_err_m = 1e-17;
  const std::string csv = executedCsv({row});
  std::istringstream in(csv);
  std::string header, line;
  std::getline(in, header);
  std::getline(in, line);
  EXPECT_EQ(header,
            "t,x,y,theta,x_ref,y_ref,theta_ref,omega_left_cmd,omega_right_cmd,omega_left,"
            "omega_right,pos_err,heading_err");
  std::istringstream cells(line);
  std::string cell;
  std::vector<double> values;
  while (std::getline(cells, cell, ',')) values.push_back(std::stod(cell));
  ASSERT_EQ(values.size(), 13u);
  EXPECT_EQ(values[0], row.t_s);
  EXPECT_EQ(values[2], row.pose.y);
  EXPECT_EQ(values[3], row.pose.theta);
  EXPECT_EQ(values[11], row.pos_err_m);
}

// A 240 Hz episode (every physics step recorded, as `parksim run` records by default).
EpisodeOutcome episodeAt240Hz(const std::string& realism) {
  EpisodeRequest r;
  r.world = std::make_shared<const World>(
      loadWorld(parksim::testing::sourceDir() + "/worlds/head_in.yaml"));
  r.realism = realism;
  return runEpisodePipeline(r);
}

void expectSameColumns(const std::vector<DataColumn>& got, const std::vector<DataColumn>& want) {
  ASSERT_EQ(got.size(), want.size());
  for (std::size_t c = 0; c < want.size(); ++c) {
    EXPECT_EQ(got[c].name, want[c].name);
    ASSERT_EQ(got[c].values.size(), want[c].values.size());
    std::size_t differing = 0;
    for (std::size_t i = 0; i < want[c].values.size(); ++i) {
      differing += std::bit_cast<std::uint64_t>(got[c].values[i]) !=
                   std::bit_cast<std::uint64_t>(want[c].values[i]);
    }
    EXPECT_EQ(differing, 0u) << want[c].name;
  }
}

class ExecutedRecord : public ::testing::TestWithParam<const char*> {};

TEST_P(ExecutedRecord, NpzOfA240HzEpisodeIsAThirdOfTheCsvAndReadsBackBitExact) {
  const EpisodeOutcome out = episodeAt240Hz(GetParam());
  const bool realism = out.execution.realism.active();
  ASSERT_EQ(out.episode.rows.size(), static_cast<std::size_t>(out.episode.metrics.steps) + 1);
  const std::filesystem::path dir =
      parksim::testing::testOutputDir(std::string("ExecutedRecord.") + GetParam());
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const std::string csv = (dir / "executed.csv").string();
  const std::string npz = (dir / "executed.npz").string();
  writeExecutedFile(csv, out.episode.rows, realism, RecordFormat::kCsv);
  writeExecutedFile(npz, out.episode.rows, realism, RecordFormat::kNpz);
  const auto csv_bytes = std::filesystem::file_size(csv);
  const auto npz_bytes = std::filesystem::file_size(npz);
  RecordProperty("csv_bytes", std::to_string(csv_bytes));
  RecordProperty("npz_bytes", std::to_string(npz_bytes));
  EXPECT_LE(3 * npz_bytes, csv_bytes) << npz_bytes << " of " << csv_bytes << " bytes";

  const std::vector<DataColumn> want = executedColumns(out.episode.rows, realism);
  EXPECT_EQ(want.size(), realism ? 26u : 13u);
  expectSameColumns(readRecordFile(npz), want);
  expectSameColumns(readRecordFile(csv), want);  // the CSV's 17 digits are exact too

  // Same rows, same bytes (no time stamp in the archive).
  const std::string again = (dir / "again.npz").string();
  writeExecutedFile(again, out.episode.rows, realism, RecordFormat::kNpz);
  EXPECT_EQ(parksim::testing::slurp(again), parksim::testing::slurp(npz));
}

INSTANTIATE_TEST_SUITE_P(Realism, ExecutedRecord, ::testing::Values("ideal", "lab"));

TEST(ExecutedFile, SensorsNpzHoldsTheCsvColumns) {
  std::vector<PoseMeasurement> samples(3);
  for (int i = 0; i < 3; ++i) {
    samples[i].arrival_step = 10 * i + 6;
    samples[i].taken_step = 10 * i;
    samples[i].pose = {0.1 * i, 1.0 / (i + 3), -0.5};
  }
  const std::vector<DataColumn> c = sensorsColumns(samples, 1.0 / 240.0);
  ASSERT_EQ(c.size(), 5u);
  EXPECT_EQ(c[0].name, "t_received");
  EXPECT_EQ(c[0].values[1], 16.0 / 240.0);
  EXPECT_EQ(c[3].values[2], 1.0 / 5.0);
  EXPECT_EQ(sensorsCsv(samples, 1.0 / 240.0).substr(0, 29), "t_received,t_taken,x,y,theta\n");
}

TEST(ExecutedFile, RecordFormatsByName) {
  EXPECT_EQ(recordFormatFromString("npz"), RecordFormat::kNpz);
  EXPECT_EQ(executedFileName(RecordFormat::kNpz), "executed.npz");
  EXPECT_EQ(sensorsFileName(RecordFormat::kCsv), "sensors.csv");
  EXPECT_THROW(recordFormatFromString("gz"), Error);
}

}  // namespace
}  // namespace parksim
