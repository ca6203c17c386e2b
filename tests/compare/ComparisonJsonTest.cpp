// A comparison as its page's data: every metric's numbers and line, NaN as null, and each
// group's paired episodes ordered worst first (newly failed, failed in both, then by how much
// the max tracking error grew).

#include "parksim/compare/ComparisonJson.h"

#include <gtest/gtest.h>

namespace parksim {
namespace {

using Json = nlohmann::ordered_json;

Json row(const std::string& id, bool met, double max_err_m, const std::string& world = "lot") {
  Json r;
  r["episode_id"] = id;
  r["world"] = world;
  r["planner"] = "rrt";
  r["status"] = met ? "met" : "contact";
  r["met_tolerance"] = met;
  r["max_pos_err_m"] = max_err_m;
  r["goal_pos_err_m"] = 1e-4;
  return r;
}

TEST(ComparisonJsonTest, PairsComeWorstFirst) {
  // a: met -> met, error +1 mm; b: met -> failed; c: failed in both; d: met -> met, +3 mm;
  // e only in the baseline (and z in another group) are not pairs of this group.
  const std::vector<Json> baseline = {row("a", true, 1e-3),  row("b", true, 1e-3),
                                      row("c", false, 1e-3), row("d", true, 1e-3),
                                      row("e", true, 1e-3),  row("z", true, 1e-3, "other")};
  const std::vector<Json> candidate = {row("a", true, 2e-3), row("b", false, 1e-3),
                                       row("c", false, 1e-3), row("d", true, 4e-3),
                                       row("z", true, 1e-3, "other")};
  const CompareDef def;
  const TableComparison t = compareTables(baseline, candidate, def);
  const nlohmann::json j = comparisonJson(t, def, {"base", "cand", 6, 5}, baseline, candidate);
  ASSERT_EQ(j["groups"].size(), 2u);
  const nlohmann::json& g = j["groups"][0];
  EXPECT_EQ(g["name"], "lot / rrt / world");
  std::vector<std::string> order;
  for (const nlohmann::json& e : g["episodes"]) order.push_back(e["id"]);
  EXPECT_EQ(order, (std::vector<std::string>{"b", "c", "d", "a"}));
  EXPECT_EQ(g["episodes"][0]["baseline"]["met"], true);
  EXPECT_EQ(g["episodes"][0]["candidate"]["status"], "contact");
  EXPECT_EQ(g["episodes"][2]["candidate"]["max_pos_err_m"], 4e-3);
  EXPECT_EQ(j["groups"][1]["episodes"].size(), 1u);
}

TEST(ComparisonJsonTest, MetricsKeepTheirNumbersAndLine) {
  const std::vector<Json> baseline = {row("a", true, 1e-3), row("b", true, 1e-3)};
  const CompareDef def;
  const TableComparison t = compareTables(baseline, baseline, def);
  const nlohmann::json j = comparisonJson(t, def, {"base", "cand", 2, 2}, baseline, baseline);
  EXPECT_EQ(j["regression"], false);
  EXPECT_EQ(j["tests"], t.tests);
  EXPECT_EQ(j["settings"]["confidence"], def.confidence);
  const nlohmann::json& rate = j["groups"][0]["metrics"][0];
  EXPECT_EQ(rate["name"], "success rate");
  EXPECT_EQ(rate["baseline_met"], 2);
  EXPECT_TRUE(rate["ci_low"].is_null());  // NaN for a rate: null in JSON
  EXPECT_EQ(rate["line"], metricLine(t.groups[0].metrics[0], def));
  const nlohmann::json& p95 = j["groups"][0]["metrics"][2];
  EXPECT_EQ(p95["tested"], false);  // two values, fewer than min_samples
  EXPECT_FALSE(p95["note"].get<std::string>().empty());
}

// Compared across the controller, each pair holds both ids (the candidate's page is under its
// own), the group and the document say what was compared across; without it neither appears.
TEST(ComparisonJsonTest, AcrossColumnsGiveTheCandidatesOwnIds) {
  std::vector<Json> baseline;
  std::vector<Json> candidate;
  for (int k = 0; k < 3; ++k) {
    Json b = row("b" + std::to_string(k), true, 1e-3);
    b["controller"] = "tracking";
    b["noise_seed"] = k;
    Json c = b;
    c["episode_id"] = "c" + std::to_string(k);
    c["controller"] = "pure-pursuit";
    baseline.push_back(b);
    candidate.push_back(c);
  }
  CompareDef def;
  // Without --across two controllers are two groups: compareTables refuses
  // (TableComparisonTest.cpp); the JSON of a plain comparison has no "across".
  const nlohmann::json plain =
      comparisonJson(compareTables(baseline, baseline, def), def, {}, baseline, baseline);
  EXPECT_FALSE(plain.contains("across"));
  def.across = {"controller"};
  const nlohmann::json j =
      comparisonJson(compareTables(baseline, candidate, def), def, {}, baseline, candidate);
  EXPECT_EQ(j["across"], nlohmann::json::array({"controller"}));
  EXPECT_EQ(j["groups"][0]["across"][0], nlohmann::json({{"column", "controller"},
                                                         {"baseline", "tracking"},
                                                         {"candidate", "pure-pursuit"}}));
  const nlohmann::json& episodes = j["groups"][0]["episodes"];
  ASSERT_EQ(episodes.size(), 3u);
  for (const nlohmann::json& e : episodes) {
    EXPECT_EQ("c" + e["id"].get<std::string>().substr(1), e["candidate_id"]);
  }
}

}  // namespace
}  // namespace parksim
