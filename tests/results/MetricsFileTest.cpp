// metrics.json's flat keys, read back.

#include "parksim/results/episode/MetricsFile.h"

#include <algorithm>
#include <vector>

#include <gtest/gtest.h>

#include "parksim/core/stats/Quantile.h"

namespace parksim {
namespace {

EpisodeMetrics goodMetrics() {
  EpisodeMetrics m;
  m.max_pos_err_m = 0.001;
  m.goal_pos_err_m = 0.001;
  m.goal_heading_err_deg = 0.5;
  m.goal_reached = true;
  return m;
}

TEST(MetricsFile, MetricsJsonHasTheFlatKeys) {
  EpisodeMetrics m = goodMetrics();
  m.parked.push_back({"robot_3", 1e-5, 0.0});
  m.contact_events.push_back({0.5, 2, "wall_1"});
  m.contact_events.push_back({0.9, 2, "wall_1"});
  m.contacts = 2;
  const nlohmann::json j = metricsToJson(m);
  for (const char* key :
       {"max_pos_err_m", "rms_pos_err_m", "final_pos_err_m", "final_heading_err_deg", "contacts",
        "goal_reached", "sim_time_s", "wall_time_s", "goal_pos_err_m", "goal_heading_err_deg",
        "max_parked_displacement_m", "tracking", "parked_displacement_m.robot_3"}) {
    EXPECT_TRUE(j.contains(key)) << key;
  }
  for (const auto& [key, value] : j.items()) {
    if (key == "contact_bodies") continue;
    EXPECT_TRUE(value.is_primitive()) << key;
  }
  EXPECT_EQ(j["contact_bodies"], nlohmann::json::array({"wall_1"}));
  EXPECT_EQ(j["tracking"], "closed");
  const EpisodeMetrics back = metricsFromJson(j);
  EXPECT_EQ(back.max_pos_err_m, m.max_pos_err_m);
  EXPECT_EQ(back.contacts, 2);
}

TEST(MetricsFile, TheDocumentCarriesTheVerdictTheToleranceAndTheRealisations) {
  MetricsDocument doc;
  doc.metrics = goodMetrics();
  doc.world = "worlds/x.yaml";
  doc.scenario = "x";
  doc.tolerance.max_contacts = 3;
  doc.status = "contact";
  doc.met = false;
  doc.failure = "touched wall at 1.000 s (4 contact events, at most 3)";
  doc.plan_summary = {{"planner", "rrt"},
                      {"phase_times_s", {{"sampling", 0.5}}},
                      {"cost_history", nlohmann::json::array()}};
  const nlohmann::json one = metricsDocumentJson(doc);
  EXPECT_EQ(one["status"], "contact");
  EXPECT_EQ(one["met_tolerance"], false);
  EXPECT_EQ(one["failure"], doc.failure);
  EXPECT_EQ(one["tolerance.max_contacts"], 3);
  EXPECT_EQ(one["plan_planner"], "rrt");
  EXPECT_EQ(one["plan_phase_times_s.sampling"], 0.5);
  EXPECT_FALSE(one.contains("plan_cost_history"));
  EXPECT_FALSE(one.contains("realisations.count"));
  EXPECT_TRUE(one.contains("provenance.parksim_version"));

  EpisodeMetrics worse = goodMetrics();
  worse.max_pos_err_m = 0.003;
  doc.realisations = {{1, goodMetrics(), "met", true}, {2, worse, "tolerance_missed", false}};
  const nlohmann::json two = metricsDocumentJson(doc);
  EXPECT_EQ(two["realisations.count"], 2);
  EXPECT_EQ(two["realisation.1.status"], "tolerance_missed");
  EXPECT_EQ(two["realisation.1.success"], false);
  EXPECT_EQ(two["realisations.success_fraction"], 0.5);
  EXPECT_EQ(two["realisations.max_pos_err_m.max"], 0.003);
}

// metrics.json's median and p95 of the realisations are the quantiles the report, the pages and
// `parksim compare` give (type 7, NumPy's default), computed here from their definition: for
// 20 values 1..20 mm, h = 0.95 * 19 = 18.05, so p95 = 19 + 0.05 * (20 - 19) = 19.05 mm (the
// nearest rank would be 19), the median 10.5 mm.
TEST(MetricsFile, TheRealisationsQuantilesAreTheOneDefinition) {
  MetricsDocument doc;
  doc.metrics = goodMetrics();
  std::vector<double> errors_m;
  for (int k = 20; k >= 1; --k) {  // any order
    EpisodeMetrics m = goodMetrics();
    m.max_pos_err_m = 1e-3 * k;
    errors_m.push_back(m.max_pos_err_m);
    doc.realisations.push_back({static_cast<std::uint64_t>(k), m, "met", true});
  }
  std::sort(errors_m.begin(), errors_m.end());
  const double h = 0.95 * 19.0;
  const double predicted_p95 = errors_m[18] + (h - 18.0) * (errors_m[19] - errors_m[18]);
  const nlohmann::json j = metricsDocumentJson(doc);
  EXPECT_NEAR(j["realisations.max_pos_err_m.p95"].get<double>(), 19.05e-3, 1e-15);
  EXPECT_DOUBLE_EQ(j["realisations.max_pos_err_m.p95"].get<double>(), predicted_p95);
  EXPECT_DOUBLE_EQ(j["realisations.max_pos_err_m.p95"].get<double>(), quantile7(errors_m, 0.95));
  EXPECT_NEAR(j["realisations.max_pos_err_m.median"].get<double>(), 10.5e-3, 1e-15);
  EXPECT_EQ(j["realisations.max_pos_err_m.max"], 20e-3);
}

}  // namespace
}  // namespace parksim
