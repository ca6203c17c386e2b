// The one episode record: each key once per place, fields read from the facts they name, the
// table's columns and the docs' column table from it. The agreement of run, a sweep and
// Python on one real episode is tests/pipeline/test_episode_record.py.

#include "parksim/results/tables/EpisodeRecord.h"

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <set>
#include <string>

#include <gtest/gtest.h>

#include "parksim/results/episode/MetricsFile.h"
#include "parksim/results/episode/PlanFile.h"
#include "parksim/results/tables/ResultsFile.h"
#include "tests/support/TestPaths.h"

namespace parksim {
namespace {

TEST(EpisodeRecord, EachKeyOncePerPlaceWithAMeaning) {
  std::set<std::string_view> table;
  std::set<std::string_view> metrics;
  for (const EpisodeField& f : episodeFields()) {
    EXPECT_FALSE(f.key.empty() && f.metrics_key.empty()) << f.meaning;
    EXPECT_FALSE(f.meaning.empty()) << f.key;
    if (!f.key.empty()) {
      EXPECT_TRUE(table.insert(f.key).second) << f.key;
      EXPECT_EQ(findField(f.key), &f) << f.key;
      EXPECT_FALSE(isSetKey(f.key)) << f.key;
    }
    if (!f.metrics_key.empty()) EXPECT_TRUE(metrics.insert(f.metrics_key).second) << f.metrics_key;
    // What the writer does not read from the outcome, it is given: the parameters, provenance.
    if (f.read == nullptr) {
      EXPECT_TRUE(f.group == FieldGroup::kIdentity || f.group == FieldGroup::kParameter ||
                  f.group == FieldGroup::kProvenance || f.group == FieldGroup::kSeal)
          << f.key;
    }
  }
  EXPECT_EQ(episodeFields().back().key, "row_checksum");
  EXPECT_EQ(findField("parked_displacement_m.robot_5")->key, "parked_displacement_m");
  EXPECT_EQ(findField("parked_displacement_m."), nullptr);
  EXPECT_TRUE(isSetKey("robot.max_wheel_speed_radps"));
  EXPECT_TRUE(isSetKey("planner.step_m"));
  EXPECT_FALSE(isSetKey("realism"));
}

// Every field read from the facts it needs and no others: measurements alone give the
// measurement fields (Python's Episode.metrics, a realisation's), a verdict adds the outcome.
TEST(EpisodeRecord, FieldsAreReadFromTheFactsTheyName) {
  EpisodeMetrics m;
  m.max_pos_err_m = 0.002;
  m.estimator = "fused";
  m.pose_samples_dropped = 3;
  m.parked.push_back({"robot_5", 1e-4, 5e-5});
  EpisodeFacts facts;
  facts.metrics = &m;
  const nlohmann::json only_metrics = metricsRecord(facts);
  EXPECT_EQ(only_metrics, metricsToJson(m));
  EXPECT_EQ(only_metrics.at("max_pos_err_m"), 0.002);
  EXPECT_EQ(only_metrics.at("estimator"), "fused");
  EXPECT_EQ(only_metrics.at("parked_displacement_m.robot_5"), 1e-4);
  EXPECT_FALSE(only_metrics.contains("status"));
  EXPECT_FALSE(only_metrics.contains("plan_status"));

  facts.judged = true;
  facts.status = "goal_missed";
  facts.failure = "ended far";
  const nlohmann::json summary = {{"status", "exact_solution"},
                                  {"iterations", 12},
                                  {"planning_time_s", 0.5},
                                  {"duration_s", 9.0}};
  facts.plan_summary = &summary;
  facts.world_hash = "00000000000000aa";
  nlohmann::ordered_json row;
  appendRecord(facts, row);
  EXPECT_EQ(row["status"], "goal_missed");
  EXPECT_EQ(row["met_tolerance"], false);
  EXPECT_EQ(row["plan_status"], "exact_solution");
  EXPECT_EQ(row["plan_iterations"], 12);
  EXPECT_EQ(row["plan_time_s"], 0.5);
  EXPECT_EQ(row["plan_duration_s"], 9.0);
  EXPECT_EQ(row["estimator"], "fused");
  EXPECT_EQ(row["pose_samples_dropped"], 3);
  EXPECT_EQ(row["parked_displacement_m.robot_5"], 1e-4);
  EXPECT_EQ(row["world_hash"], "00000000000000aa");
  EXPECT_FALSE(row.contains("episode_wall_s"));  // not measured
  EXPECT_FALSE(row.contains("tracking"));        // a parameter: the writer's
  EXPECT_FALSE(row.contains("plan_cost_m"));     // not in the summary
  // In the table's order.
  std::vector<std::string> keys;
  for (const auto& [key, value] : row.items()) keys.push_back(key);
  std::vector<std::string> order;
  for (const EpisodeField& f : episodeFields()) {
    for (const std::string& k : keys) {
      if (findField(k) == &f) order.push_back(k);
    }
  }
  EXPECT_EQ(keys, order);
}

// A row's phase times are plan.json's, every phase of them (the A* planners' heuristic, every
// planner's timing), under the same names and in the same order.
TEST(EpisodeRecord, PhaseTimesAreEveryPhaseOfPlanJson) {
  PlanResult plan;
  PhaseTimes& t = plan.stats.times;
  t.sampling_s = 0.01;
  t.nearest_s = 0.02;
  t.steering_s = 0.03;
  t.collision_s = 0.04;
  t.goal_check_s = 0.05;
  t.rewiring_s = 0.06;
  t.connection_s = 0.07;
  t.smoothing_s = 0.08;
  t.heuristic_s = 0.25;
  t.timing_s = 0.5;
  Scenario scenario;
  const nlohmann::json summary = planSummary(scenario, PlanSetup{}, plan);
  EpisodeFacts facts;
  facts.plan = &plan;
  facts.plan_summary = &summary;
  nlohmann::ordered_json row;
  appendRecord(facts, row);
  const nlohmann::ordered_json& phases = row.at("plan_phase_times_s");
  EXPECT_EQ(phases.at("heuristic"), 0.25);
  EXPECT_EQ(phases.at("timing"), 0.5);
  std::vector<std::pair<std::string, double>> in_row, in_plan_json;
  for (const auto& [name, s] : phases.items()) in_row.emplace_back(name, s.get<double>());
  for (const auto& [name, s] : summary.at("phase_times_s").items()) {
    in_plan_json.emplace_back(name, s.get<double>());
  }
  std::sort(in_plan_json.begin(), in_plan_json.end());  // nlohmann::json sorts its keys
  std::vector<std::pair<std::string, double>> sorted_row = in_row;
  std::sort(sorted_row.begin(), sorted_row.end());
  EXPECT_EQ(sorted_row, in_plan_json);
  ASSERT_EQ(in_row.size(), 10u);
  EXPECT_EQ(in_row.front().first, "sampling");
  EXPECT_EQ(in_row.back().first, "timing");
}

TEST(EpisodeRecord, SetColumnsComeAfterTheParameters) {
  const std::vector<std::string> plain = recordColumns();
  const std::vector<std::string> with = recordColumns({"a.b", "planner.k"});
  ASSERT_EQ(with.size(), plain.size() + 2);
  EXPECT_EQ(plain[setColumnsPosition() - 1], "sample");
  EXPECT_EQ(with[setColumnsPosition()], "a.b");
  EXPECT_EQ(with[setColumnsPosition() + 1], "planner.k");
  EXPECT_EQ(with[setColumnsPosition() + 2], "status");
  EXPECT_EQ(setColumnsOfHeader(csvHeader(with).substr(0, csvHeader(with).size() - 1)),
            (std::vector<std::string>{"a.b", "planner.k"}));
  EXPECT_FALSE(setColumnsOfHeader("episode_id,world"));
}

// docs/sweeps.md's column table is the record's. PARKSIM_UPDATE_DOCS=1 writes it there.
TEST(EpisodeRecord, TheDocsColumnTableIsTheRecords) {
  const std::string path = testing::sourceDir() + "/docs/sweeps.md";
  std::ifstream in(path);
  std::string doc((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string begin =
      "<!-- columns: recordColumnsMarkdown() (parksim/results/tables/EpisodeRecord.cpp); "
      "tests/results/EpisodeRecordTest.cpp checks it -->\n";
  const std::string end = "<!-- end of columns -->";
  const std::size_t b = doc.find(begin);
  const std::size_t e = doc.find(end);
  ASSERT_NE(b, std::string::npos) << path << " lacks: " << begin;
  ASSERT_NE(e, std::string::npos);
  const std::string table = recordColumnsMarkdown();
  if (const char* update = std::getenv("PARKSIM_UPDATE_DOCS"); update != nullptr) {
    doc.replace(b + begin.size(), e - b - begin.size(), table);
    std::ofstream(path, std::ios::binary) << doc;
    return;
  }
  EXPECT_EQ(doc.substr(b + begin.size(), e - b - begin.size()), table)
      << "docs/sweeps.md's column table is not the record's: PARKSIM_UPDATE_DOCS=1 "
         "build/tests/results/results_tests --gtest_filter='EpisodeRecord.TheDocs*' writes it";
}

}  // namespace
}  // namespace parksim
