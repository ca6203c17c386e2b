// `parksim report` per parameter: which parameters varied, their levels (values or bins), the
// met share's Wilson interval, and where success turns to failure in a one-parameter study.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "parksim/report/Report.h"
#include "tests/sweep/SweepTestSupport.h"

namespace parksim {
namespace {

using Json = nlohmann::ordered_json;

Json row(std::uint64_t seed, double value, bool met, double err_m = 0.001) {
  Json r;
  r["episode_id"] = std::to_string(seed) + "-" + std::to_string(value);
  r["world"] = "lot";
  r["planner"] = "rrt";
  r["seed"] = seed;
  r["realism"] = "world";
  r["robot.max_wheel_speed_radps"] = value;
  r["status"] = met ? "met" : "goal_missed";
  r["met_tolerance"] = met;
  r["max_pos_err_m"] = err_m;
  r["goal_pos_err_m"] = err_m / 2;
  return r;
}

TEST(ParameterReport, TheMetShareHasTheWilsonInterval) {
  // 0 of 1: [0, z^2 / (1 + z^2)]; 10 of 10: [1 / (1 + z^2 / 10), 1] (Wilson's formula at
  // p = 0 and p = 1).
  const double z2 = 1.959963984540054 * 1.959963984540054;
  std::vector<Json> rows = {row(1, 1.0, false)};
  for (std::uint64_t s = 1; s <= 10; ++s) rows.push_back(row(s, 2.0, true));
  const std::vector<ParameterStudy> studies = parameterStudies(rows);
  ASSERT_EQ(studies.size(), 1u) << studies.back().parameter;
  const ParameterStudy& st = studies[0];
  EXPECT_EQ(st.parameter, "robot.max_wheel_speed_radps");
  EXPECT_TRUE(st.numeric);
  ASSERT_EQ(st.levels.size(), 2u);
  EXPECT_EQ(st.levels[0].label, "1");
  EXPECT_DOUBLE_EQ(st.levels[0].met_low, 0.0);
  EXPECT_NEAR(st.levels[0].met_high, z2 / (1 + z2), 1e-12);
  EXPECT_EQ(st.levels[1].episodes, 10);
  EXPECT_EQ(st.levels[1].met, 10);
  EXPECT_NEAR(st.levels[1].met_low, 1 / (1 + z2 / 10), 1e-12);
  EXPECT_DOUBLE_EQ(st.levels[1].met_high, 1.0);
  // Seeds varied too: a replication, not a parameter.
}

TEST(ParameterReport, EveryVaryingParameterCategoricalOrNumericAndManyValuesInBins) {
  std::vector<Json> rows;
  for (int i = 0; i < 100; ++i) {
    Json r = row(1, 5.0 + 0.01 * i, i % 3 != 0);
    r["planner"] = i % 2 == 0 ? "rrt" : "rrt-connect";
    r["sample"] = i;
    rows.push_back(r);
  }
  const std::vector<ParameterStudy> studies = parameterStudies(rows);
  ASSERT_EQ(studies.size(), 2u);  // sample is a replication
  EXPECT_EQ(studies[0].parameter, "planner");
  EXPECT_FALSE(studies[0].numeric);
  ASSERT_EQ(studies[0].levels.size(), 2u);
  EXPECT_EQ(studies[0].levels[1].label, "rrt-connect");
  EXPECT_EQ(studies[0].levels[1].episodes, 50);
  const ParameterStudy& speed = studies[1];
  EXPECT_TRUE(speed.binned);
  ASSERT_EQ(speed.levels.size(), 10u);
  int total = 0;
  for (std::size_t b = 0; b < speed.levels.size(); ++b) {
    EXPECT_EQ(speed.levels[b].episodes, 10) << b;
    total += speed.levels[b].episodes;
    // The bin's mean value: values 5 + 0.01 i for i in 10b .. 10b + 9.
    EXPECT_NEAR(speed.levels[b].x, 5.0 + 0.01 * (10.0 * b + 4.5), 1e-9) << b;
  }
  EXPECT_EQ(total, 100);
  EXPECT_EQ(speed.levels[0].label, "[5, 5.09]");
  const std::string md = parametersMarkdown(studies, std::nullopt);
  EXPECT_NE(md.find("### robot.max_wheel_speed_radps"), std::string::npos);
  EXPECT_NE(md.find("10 bins"), std::string::npos);
  const std::string csv = parametersCsv(studies);
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 1 + 2 + 10);
}

std::optional<ParameterBoundary> boundaryOf(const std::vector<std::pair<double, bool>>& values) {
  std::vector<Json> rows;
  for (const auto& [v, met] : values) {
    rows.push_back(row(1, v, met));
    rows.push_back(row(2, v, met));
  }
  const std::vector<ParameterStudy> studies = parameterStudies(rows);
  EXPECT_EQ(studies.size(), 1u);
  return parameterBoundary(rows, studies.at(0));
}

TEST(ParameterReport, TheBoundaryIsBetweenTheLastMetAndTheFirstFailedValue) {
  // Met at low speeds, failed from 8 on.
  auto b = boundaryOf({{4, true}, {6, true}, {8, false}, {10, false}});
  ASSERT_TRUE(b);
  EXPECT_EQ(b->last_met, 6);
  EXPECT_EQ(b->first_failed, 8);
  EXPECT_TRUE(b->monotone);
  // The other way (a controller rate: too slow fails), walked from the end that met.
  b = boundaryOf({{5, false}, {10, true}, {20, true}, {40, true}});
  ASSERT_TRUE(b);
  EXPECT_EQ(b->last_met, 10);
  EXPECT_EQ(b->first_failed, 5);
  // Failing, then meeting again further on: said so.
  b = boundaryOf({{1, true}, {2, false}, {3, true}, {4, false}});
  ASSERT_TRUE(b);
  EXPECT_EQ(b->first_failed, 2);
  EXPECT_FALSE(b->monotone);
  const std::string md = parametersMarkdown({}, b);
  EXPECT_NE(md.find("**Boundary** (robot.max_wheel_speed_radps): every episode met its "
                    "tolerance up to 1; from 2 up some did not (further on, some values meet "
                    "again)"),
            std::string::npos)
      << md;
  // No turn: met everywhere, or at both ends.
  EXPECT_FALSE(boundaryOf({{1, true}, {2, true}}));
  EXPECT_FALSE(boundaryOf({{1, true}, {2, false}, {3, true}}));
  EXPECT_FALSE(boundaryOf({{1, false}, {2, false}}));
}

TEST(ParameterReport, TheReportHasATableAndAPlotPerParameter) {
  std::vector<Json> rows;
  for (double v : {6.0, 8.0, 10.0}) {
    for (std::uint64_t s = 1; s <= 3; ++s) rows.push_back(row(s, v, v < 9.0, 0.001 * v));
  }
  const std::string dir = testing::scratchDir();
  const std::vector<std::string> written = writeReport(rows, "speeds", dir);
  EXPECT_NE(
      std::find(written.begin(), written.end(), dir + "/parameter_robot.max_wheel_speed_radps.png"),
      written.end());
  EXPECT_TRUE(std::filesystem::file_size(dir + "/parameter_robot.max_wheel_speed_radps.png") > 0);
  std::ifstream in(dir + "/summary.md");
  const std::string md((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_NE(md.find("## Per parameter"), std::string::npos);
  EXPECT_NE(md.find("| 10 | 3 | 0/3 (0%) |"), std::string::npos) << md;
  EXPECT_NE(md.find("up to 8; from 10 up"), std::string::npos) << md;
}

}  // namespace
}  // namespace parksim
