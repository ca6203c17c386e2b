// What differs between two configurations (compare/ConfigurationDiff.h): parameter and
// provenance columns whose values differ, and the spec lines only one side has.

#include "parksim/compare/ConfigurationDiff.h"

#include <gtest/gtest.h>

namespace parksim {
namespace {

using Json = nlohmann::ordered_json;

Json row(const std::string& planner, int seed, const std::string& commit, double err) {
  Json r;
  r["episode_id"] = planner + std::to_string(seed);
  r["world"] = "head_in";
  r["planner"] = planner;
  r["seed"] = seed;
  r["set.robot.max_wheel_speed_radps"] = 6;
  r["status"] = "met";
  r["max_pos_err_m"] = err;  // a measurement: never a difference
  r["git_commit"] = commit;
  return r;
}

TEST(ConfigurationDiff, ColumnsWhoseValuesDifferAreListedInTheRecordsOrder) {
  const std::vector<Json> base = {row("rrt", 1, "abc", 1e-4), row("rrt", 2, "abc", 2e-4)};
  std::vector<Json> cand = {row("rrt-star", 1, "def", 3e-4), row("rrt-star", 2, "def", 1e-4)};
  cand[1]["set.robot.max_wheel_speed_radps"] = 8;
  cand[1]["controller"] = "pure-pursuit";
  const auto d = columnDifferences(base, cand);
  ASSERT_EQ(d.size(), 4u);
  EXPECT_EQ(d[0].what, "planner");
  EXPECT_EQ(d[0].baseline, "rrt");
  EXPECT_EQ(d[0].candidate, "rrt-star");
  EXPECT_EQ(d[1].what, "set.robot.max_wheel_speed_radps");
  EXPECT_EQ(d[1].baseline, "6");
  EXPECT_EQ(d[1].candidate, "6, 8");
  EXPECT_EQ(d[2].what, "git_commit");
  EXPECT_EQ(d[2].baseline, "abc");
  EXPECT_EQ(d[2].candidate, "def");
  EXPECT_EQ(d[3].what, "controller");
  EXPECT_EQ(d[3].baseline, "(none)");
  EXPECT_EQ(d[3].candidate, "pure-pursuit");
  EXPECT_TRUE(columnDifferences(base, base).empty());
}

TEST(ConfigurationDiff, ManyValuesAreCounted) {
  std::vector<Json> base;
  for (int s = 1; s <= 9; ++s) base.push_back(row("rrt", s, "abc", 1e-4));
  const auto d = columnDifferences(base, {row("rrt", 1, "abc", 1e-4)});
  ASSERT_EQ(d.size(), 1u);
  EXPECT_EQ(d[0].what, "seed");
  EXPECT_EQ(d[0].baseline, "1, 2, 3, 4, 5, ... (9 values)");
  EXPECT_EQ(d[0].candidate, "1");
}

TEST(ConfigurationDiff, SpecLinesOnlyOneSideHas) {
  const std::string base = "format: parksim-sweep/1\n# a comment\nname: lab\n\nrealism: lab\n";
  const std::string cand =
      "format: parksim-sweep/1\nrealism: lab\nname: lab   \n# another\ntolerance: {max_pos_err_m: "
      "0.0011}\n";
  const auto d = specDifferences(base, cand);
  ASSERT_EQ(d.size(), 1u);
  EXPECT_EQ(d[0].what, "spec");
  EXPECT_EQ(d[0].baseline, "");
  EXPECT_EQ(d[0].candidate, "tolerance: {max_pos_err_m: 0.0011}");
  const auto back = specDifferences(cand, base);
  ASSERT_EQ(back.size(), 1u);
  EXPECT_EQ(back[0].baseline, "tolerance: {max_pos_err_m: 0.0011}");
  EXPECT_EQ(differencesJson(d)[0]["candidate"], "tolerance: {max_pos_err_m: 0.0011}");
}

}  // namespace
}  // namespace parksim
