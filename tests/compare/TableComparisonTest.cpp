// `parksim compare`'s decision on tables with known truth (tests/compare/SyntheticTables.h),
// written through the results-table writer and read back as the command reads them: pairing,
// regressions and improvements, groups too small to test, bad tables, and `--across`. Its rates
// over many trials are in TableComparisonRatesTest.cpp.

#include "parksim/compare/TableComparison.h"

#include <bit>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <random>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "parksim/compare/ComparedTable.h"
#include "parksim/core/io/Error.h"
#include "parksim/results/tables/ResultsTable.h"
#include "parksim/sweep/spec/EpisodeParams.h"
#include "tests/compare/SyntheticTables.h"
#include "tests/support/TestPaths.h"

namespace parksim {
namespace {

using ::testing::HasSubstr;
using synthetic::Json;
using synthetic::kLab;
using synthetic::kWide;
using synthetic::kWorlds;
using synthetic::syntheticRow;
using synthetic::syntheticTable;
using synthetic::throughTheWriter;
using synthetic::trackingFlagged;

TEST(TableComparison, SameTablesArePairedAndNeverAlarm) {
  std::mt19937_64 rng(3);
  const std::vector<Json> rows = syntheticTable(1, kWide, rng);
  const TableComparison t = compareTables(rows, rows, CompareDef{});
  ASSERT_EQ(t.groups.size(), 3u);
  EXPECT_EQ(t.tests, 15);
  EXPECT_FALSE(t.regression());
  for (const GroupComparison& g : t.groups) {
    EXPECT_TRUE(g.paired);
    EXPECT_EQ(g.shared_ids, 20);
    for (const MetricComparison& m : g.metrics) EXPECT_DOUBLE_EQ(m.p, 1.0) << m.name;
  }
}

TEST(TableComparison, ASignificantSuccessRateDropIsARegression) {
  std::mt19937_64 rng(4);
  const std::vector<Json> baseline = syntheticTable(1, kLab, rng);
  std::vector<Json> candidate = baseline;
  int flipped = 0;
  for (Json& row : candidate) {
    if (row["world"] == "parallel" && row["met_tolerance"].get<bool>() && flipped < 10) {
      row["met_tolerance"] = false;
      ++flipped;
    }
  }
  const TableComparison paired = compareTables(baseline, candidate, CompareDef{});
  ASSERT_TRUE(paired.regression());
  const MetricComparison& rate = paired.groups[1].metrics[0];
  EXPECT_EQ(paired.groups[1].world, "parallel");
  EXPECT_EQ(rate.name, "success rate");
  EXPECT_TRUE(rate.regression);
  EXPECT_NEAR(rate.p, 1.0 / 1024.0, 1e-15);  // McNemar: 10 of 10 discordant pairs got worse
  EXPECT_NEAR(rate.p_adjusted, 15.0 / 1024.0, 1e-15);  // Holm: the smallest of 15 p-values
  // A margin of 60 points lets a drop of 50 pass.
  CompareDef lenient;
  lenient.max_success_drop = 0.6;
  EXPECT_FALSE(compareTables(baseline, candidate, lenient).regression());
}

TEST(TableComparison, ImprovementsAreReportedNeverAlarmed) {
  std::mt19937_64 rng(5);
  const std::vector<Json> baseline = syntheticTable(1, kLab, rng);
  std::vector<Json> candidate = baseline;
  for (Json& row : candidate) row["max_pos_err_m"] = 0.5 * row["max_pos_err_m"].get<double>();
  const TableComparison t = compareTables(baseline, candidate, CompareDef{});
  EXPECT_FALSE(t.regression());
  EXPECT_NEAR(t.groups[0].metrics[1].candidate / t.groups[0].metrics[1].baseline, 0.5, 1e-12);
}

TEST(TableComparison, SmallGroupsAndOneSidedGroupsAreSaidNotTested) {
  std::mt19937_64 rng(6);
  std::vector<Json> baseline = syntheticTable(1, kLab, rng);
  std::vector<Json> candidate;
  for (const Json& row : baseline) {
    if (row["world"] == "head_in" && candidate.size() < 3) candidate.push_back(row);
    if (row["world"] == "parallel") candidate.push_back(row);
  }
  baseline.erase(std::remove_if(baseline.begin(), baseline.end(),
                                [](const Json& r) { return r["world"] == "parallel"; }),
                 baseline.end());
  candidate.push_back(syntheticRow("corridor", 1, kLab, rng, 1e-3));
  const TableComparison t = compareTables(baseline, candidate, CompareDef{});
  ASSERT_EQ(t.groups.size(), 1u);
  EXPECT_FALSE(t.groups[0].paired);  // the candidate holds 3 of the baseline's 20 ids
  EXPECT_EQ(t.groups[0].shared_ids, 3);
  EXPECT_TRUE(t.groups[0].metrics[0].tested);
  EXPECT_FALSE(t.groups[0].metrics[1].tested);
  EXPECT_EQ(t.groups[0].metrics[1].note, "3 values, fewer than 5");
  // Groups are named world / planner (+smooth when smoothed) / realism.
  EXPECT_EQ(t.only_baseline,
            (std::vector<std::string>{"tight_parallel / time-a-star+smooth / lab"}));
  EXPECT_EQ(t.only_candidate, (std::vector<std::string>{"corridor / time-a-star+smooth / lab",
                                                        "parallel / time-a-star+smooth / lab"}));
}

TEST(TableComparison, BadTablesAreRefused) {
  std::mt19937_64 rng(7);
  const std::vector<Json> rows = syntheticTable(1, kLab, rng);
  const auto error = [](const std::vector<Json>& b, const std::vector<Json>& c) {
    try {
      compareTables(b, c, CompareDef{});
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_THAT(error({}, rows), HasSubstr("baseline: the table has no rows"));
  std::vector<Json> twice = rows;
  twice.push_back(rows[3]);
  EXPECT_THAT(error(rows, twice),
              HasSubstr("candidate: episode " + rows[3]["episode_id"].get<std::string>() +
                        " appears twice"));
  std::vector<Json> other = {syntheticRow("corridor", 1, kLab, rng, 1e-3)};
  EXPECT_THAT(error(rows, other), HasSubstr("no world / planner / realism group is in both"));
  CompareDef bad;
  bad.confidence = 1.0;
  EXPECT_THROW(checkCompareDef(bad), Error);
}

TEST(TableComparison, SameTablesAndSeedGiveTheSameNumbers) {
  std::mt19937_64 rng(8);
  const std::vector<Json> b = syntheticTable(1, kWide, rng);
  const std::vector<Json> c = syntheticTable(21, kWide, rng);
  const TableComparison x = compareTables(b, c, CompareDef{});
  const TableComparison y = compareTables(b, c, CompareDef{});
  for (std::size_t g = 0; g < x.groups.size(); ++g) {
    for (std::size_t m = 0; m < x.groups[g].metrics.size(); ++m) {
      EXPECT_EQ(x.groups[g].metrics[m].p, y.groups[g].metrics[m].p);
      // Bit for bit: the success rate's interval is NaN on both sides.
      EXPECT_EQ(std::bit_cast<std::uint64_t>(x.groups[g].metrics[m].ci_low),
                std::bit_cast<std::uint64_t>(y.groups[g].metrics[m].ci_low));
    }
  }
}

// A parameter study's episodes (set: values, samples) pair by id like any other: the candidate
// is the baseline's episodes with the tracking error at the highest wheel speed doubled, and
// the comparison sees them paired, each value's episodes matched to their own.
TEST(TableComparison, SetEpisodesPairByTheirIds) {
  std::mt19937_64 rng(7);
  std::vector<Json> baseline;
  for (const char* speed : {"6", "8", "10"}) {
    for (std::uint64_t sample = 0; sample < 10; ++sample) {
      EpisodeParams p;
      p.world = "head_in";
      p.sample = sample;
      p.world_set["robot.max_wheel_speed_radps"] = speed;
      p.planner_params["step_m"] = "0.05";
      Json row = syntheticRow("head_in", 1, kLab, rng, 1.7e-3);
      Json with_set;
      with_set["episode_id"] = episodeId(p);
      appendParamColumns(p, with_set);
      for (const auto& [key, value] : row.items()) {
        if (!with_set.contains(key)) with_set[key] = value;
      }
      baseline.push_back(with_set);
    }
  }
  std::vector<Json> candidate = baseline;
  for (Json& row : candidate) {
    if (row["robot.max_wheel_speed_radps"] == 10) {
      row["max_pos_err_m"] = 2.0 * row["max_pos_err_m"].get<double>();
    }
  }
  const TableComparison t = compareTables(throughTheWriter(baseline, "baseline"),
                                          throughTheWriter(candidate, "candidate"), CompareDef{});
  ASSERT_EQ(t.groups.size(), 1u);
  EXPECT_TRUE(t.groups[0].paired);
  EXPECT_EQ(t.groups[0].shared_ids, 30);
  EXPECT_TRUE(trackingFlagged(t, "head_in"));
}

// The same episodes run with another planner or controller: every other parameter as the row
// has it, the id the sweep would give them.
Json rerunWith(Json row, const std::string& planner, const std::string& controller) {
  EpisodeParams p;
  p.world = row["world"].get<std::string>();
  p.world_file = row["world_file"].get<std::string>();
  p.realism = row["realism"].get<std::string>();
  p.noise_seed = row["noise_seed"].get<std::uint64_t>();
  p.planner = planner;
  p.controller = controller;
  row["episode_id"] = episodeId(p);
  row["planner"] = planner;
  row["controller"] = controller;
  return row;
}

std::vector<Json> rerunAll(const std::vector<Json>& rows, const std::string& planner,
                           const std::string& controller, double error_factor) {
  std::vector<Json> out;
  for (const Json& row : rows) {
    out.push_back(rerunWith(row, planner, controller));
    out.back()["max_pos_err_m"] = error_factor * row["max_pos_err_m"].get<double>();
  }
  return out;
}

std::string compareError(const std::vector<Json>& b, const std::vector<Json>& c,
                         const CompareDef& def) {
  try {
    compareTables(b, c, def);
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

// The user's planner against time-a-star on the same episodes: refused as two specs without
// --across; across the planner every episode pairs with its own, and a planner whose tracking
// errors are 1.5 times larger is found out where an equal one is not.
TEST(TableComparison, AcrossThePlannerEveryEpisodePairsWithItsOwn) {
  std::mt19937_64 rng(9);
  const std::vector<Json> baseline = syntheticTable(1, kLab, rng);
  const std::vector<Json> same = rerunAll(baseline, "example", "tracking", 1.0);
  const std::vector<Json> worse = rerunAll(baseline, "example", "tracking", 1.5);
  EXPECT_THAT(compareError(baseline, same, CompareDef{}),
              HasSubstr("no world / planner / realism group is in both tables"));
  CompareDef def;
  def.across = {"planner"};
  const TableComparison t = compareTables(baseline, same, def);
  EXPECT_EQ(t.across, std::vector<std::string>{"planner"});
  ASSERT_EQ(t.groups.size(), 3u);
  EXPECT_EQ(t.groups[0].name(), "head_in / *+smooth / lab");
  for (const GroupComparison& g : t.groups) {
    EXPECT_TRUE(g.paired) << g.name();
    EXPECT_EQ(g.shared_ids, 20);
    ASSERT_EQ(g.across.size(), 1u);
    EXPECT_EQ(g.across[0].column, "planner");
    EXPECT_EQ(g.across[0].baseline, "time-a-star");
    EXPECT_EQ(g.across[0].candidate, "example");
  }
  EXPECT_FALSE(t.regression());
  const TableComparison w = compareTables(baseline, worse, def);
  for (const synthetic::World& world : kWorlds) EXPECT_TRUE(trackingFlagged(w, world.name)) << world.name;
}

// The user's controller against parksim's tracking: the groups match already (the controller
// is not in a group's name) but the ids do not, so only --across controller pairs them.
TEST(TableComparison, AcrossTheControllerTheEpisodesArePaired) {
  std::mt19937_64 rng(10);
  const std::vector<Json> baseline = syntheticTable(1, kLab, rng);
  const std::vector<Json> candidate = rerunAll(baseline, "time-a-star", "pure-pursuit", 1.0);
  // Two controllers are two groups, as two planners are: refused, pointing to --across.
  EXPECT_THAT(compareError(baseline, candidate, CompareDef{}), HasSubstr("with --across"));
  CompareDef def;
  def.across = {"controller"};
  const TableComparison t = compareTables(baseline, candidate, def);
  ASSERT_EQ(t.groups.size(), 3u);
  EXPECT_EQ(t.groups[0].name(), "head_in / time-a-star+smooth / lab");
  EXPECT_TRUE(t.groups[0].paired);
  EXPECT_EQ(t.groups[0].shared_ids, 20);
  EXPECT_EQ(t.groups[0].across[0].baseline, "tracking");
  EXPECT_EQ(t.groups[0].across[0].candidate, "pure-pursuit");
  // Paired, the test sees each episode's own change: equal errors give p = 1 exactly.
  EXPECT_DOUBLE_EQ(t.groups[0].metrics[1].p, 1.0);
}

TEST(TableComparison, AcrossColumnsAreCheckedAgainstTheTables) {
  std::mt19937_64 rng(11);
  const std::vector<Json> baseline = syntheticTable(1, kLab, rng);
  const std::vector<Json> candidate = rerunAll(baseline, "example", "tracking", 1.0);
  CompareDef def;
  def.across = {"planner", "controller.k_x"};
  EXPECT_THAT(compareError(baseline, candidate, def),
              HasSubstr("across: neither table has a column controller.k_x"));
  // Two planners in one table: their episodes would pair with the same candidate episode.
  std::vector<Json> both = baseline;
  both.push_back(candidate[4]);
  def.across = {"planner"};
  EXPECT_THAT(compareError(both, candidate, def),
              HasSubstr("baseline: episodes " + baseline[4]["episode_id"].get<std::string>() +
                        " and " + candidate[4]["episode_id"].get<std::string>() +
                        " differ only in columns compared across (planner)"));
  def.across = {"world"};
  EXPECT_THROW(checkCompareDef(def), Error);
}

}  // namespace
}  // namespace parksim
