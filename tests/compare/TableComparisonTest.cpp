// `parksim compare`'s decision on tables with known truth, written through the results-table
// writer and read back as the command reads them (issue 20's done-when):
// - power: every tracking error of one group multiplied by 1.2, 20 paired realisations per
//   group: detected in >= 90 % of seeded trials;
// - false alarms: the same code under other noise seeds (other ids: unpaired): no alarm in
//   >= 95 % of trials.
// One trial is one pair of tables. The distributions are modelled on the `lab` preset's
// measured spread (README: head_in, 20 noise seeds, max tracking error median 1.72 mm, p95
// 1.86 mm; goal error median 0.061 mm, p95 0.158 mm), and, harder, a spread six times wider
// with exponential goal errors and a fifth of the episodes failing.

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
#include "tests/support/TestPaths.h"

namespace parksim {
namespace {

using Json = nlohmann::ordered_json;
using ::testing::HasSubstr;

// A world's typical tracking error and how the realisations spread around it.
struct Spread {
  double tracking_sigma;  ///< of the log of the max tracking error
  bool wide_goal;         ///< exponential goal errors (else half-normal)
  double met_share;       ///< episodes that meet their tolerance
};

constexpr Spread kLab{0.05, false, 0.95};
constexpr Spread kWide{0.30, true, 0.80};

struct World {
  const char* name;
  double tracking_median_m;
};

constexpr World kWorlds[] = {
    {"head_in", 1.72e-3}, {"parallel", 0.95e-3}, {"tight_parallel", 2.6e-3}};

Json syntheticRow(const char* world, std::uint64_t noise_seed, const Spread& s,
                  std::mt19937_64& rng, double tracking_median_m) {
  EpisodeParams p;
  p.world = world;
  p.world_file = std::string("../") + world + ".yaml";
  p.realism = "lab";
  p.noise_seed = noise_seed;
  Json row;
  row["episode_id"] = episodeId(p);
  appendParamColumns(p, row);
  const bool met = std::uniform_real_distribution<double>(0.0, 1.0)(rng) < s.met_share;
  row["status"] = met ? "met" : "goal_missed";
  row["met_tolerance"] = met;
  row["failure"] = met ? "" : "ended 3.4 mm / 0.2 deg from the goal (tolerance 3 mm / 1.5 deg)";
  row["plan_status"] = "exact_solution";
  row["plan_solved"] = true;
  const double tracking =
      tracking_median_m * std::exp(std::normal_distribution<double>(0.0, s.tracking_sigma)(rng));
  row["max_pos_err_m"] = tracking;
  row["rms_pos_err_m"] = 0.35 * tracking;
  row["final_pos_err_m"] = 0.05 * tracking;
  const double goal = s.wide_goal ? std::exponential_distribution<double>(1.0 / 0.09e-3)(rng)
                                  : std::abs(std::normal_distribution<double>(0.0, 0.09e-3)(rng));
  row["goal_pos_err_m"] = goal;
  row["goal_reached"] = met;
  row["contacts"] = 0;
  row["episode_wall_s"] = 0.5;
  return row;
}

std::vector<Json> syntheticTable(std::uint64_t first_noise_seed, const Spread& s,
                                 std::mt19937_64& rng) {
  std::vector<Json> rows;
  for (const World& w : kWorlds) {
    for (std::uint64_t k = 0; k < 20; ++k) {
      rows.push_back(syntheticRow(w.name, first_noise_seed + k, s, rng, w.tracking_median_m));
    }
  }
  return rows;
}

// The table as `parksim compare` gets it: written by the sweep's writer, read by its reader.
// In a folder of the running test's own: ctest runs the tests in parallel processes.
std::vector<Json> throughTheWriter(const std::vector<Json>& rows, const std::string& name) {
  const std::string test = ::testing::UnitTest::GetInstance()->current_test_info()->name();
  const std::filesystem::path dir =
      parksim::testing::testOutputDir("TableComparison." + test) / name;
  std::filesystem::remove_all(dir);
  writeResultsTable(dir.string(), rows);
  return readComparedTable(dir.string()).rows;
}

bool trackingFlagged(const TableComparison& t, const std::string& world) {
  for (const GroupComparison& g : t.groups) {
    if (g.world != world) continue;
    for (const MetricComparison& m : g.metrics) {
      if (m.key == "max_pos_err_m" && m.regression) return true;
    }
  }
  return false;
}

int trials() {
  const char* env = std::getenv("PARKSIM_COMPARE_TRIALS");
  return env != nullptr ? std::max(10, std::atoi(env)) : 200;
}

// The command's settings but 2,000 bootstrap replicates (its default: 10,000): enough for
// Holm's smallest threshold over 15 tests (0.05 / 15 > 1 / 2001), and five times faster. At
// 2,000: 200 of 200 detected, 2 and 1 of 200 alarms (lab, wide); docs/ci.md.
CompareDef trialDef(int trial) {
  CompareDef def;
  def.seed = static_cast<std::uint64_t>(trial) + 1;
  def.resamples = 2000;
  return def;
}

struct Rates {
  int trials = 0;
  int hits = 0;
  double rate() const { return static_cast<double>(hits) / trials; }
};

// Trials of a planted change: baseline under noise seeds 1..20, candidate the same episodes
// (same ids) with every tracking error of head_in multiplied by `factor`.
Rates plantedTrials(const Spread& s, double factor, bool paired) {
  Rates r;
  r.trials = trials();
  for (int k = 0; k < r.trials; ++k) {
    std::mt19937_64 rng(1000 + static_cast<std::uint64_t>(k));
    const std::vector<Json> baseline = syntheticTable(1, s, rng);
    std::vector<Json> candidate = paired ? baseline : syntheticTable(21, s, rng);
    for (Json& row : candidate) {
      if (row["world"] != "head_in") continue;
      for (const char* key : {"max_pos_err_m", "rms_pos_err_m", "final_pos_err_m"}) {
        row[key] = factor * row[key].get<double>();
      }
    }
    const CompareDef def = trialDef(k);
    const TableComparison t =
        compareTables(throughTheWriter(baseline, "base"), throughTheWriter(candidate, "cand"), def);
    r.hits += trackingFlagged(t, "head_in") ? 1 : 0;
  }
  return r;
}

// Trials of unchanged code under other noise seeds: baseline 1..20, candidate 21..40.
Rates alarmTrials(const Spread& s) {
  Rates r;
  r.trials = trials();
  for (int k = 0; k < r.trials; ++k) {
    std::mt19937_64 rng(5000 + static_cast<std::uint64_t>(k));
    const std::vector<Json> baseline = syntheticTable(1, s, rng);
    const std::vector<Json> candidate = syntheticTable(21, s, rng);
    const CompareDef def = trialDef(k);
    const TableComparison t =
        compareTables(throughTheWriter(baseline, "base"), throughTheWriter(candidate, "cand"), def);
    for (const GroupComparison& g : t.groups) EXPECT_FALSE(g.paired);
    r.hits += t.regression() ? 1 : 0;
  }
  return r;
}

TEST(TableComparison, DetectsTrackingErrorsTimes1Point2With20PairedRealisations) {
  const Rates r = plantedTrials(kLab, 1.2, true);
  RecordProperty("power", std::to_string(r.rate()));
  std::printf("planted x1.2, paired, lab spread: detected in %d of %d trials\n", r.hits, r.trials);
  EXPECT_GE(r.rate(), 0.90);
}

TEST(TableComparison, NoAlarmUnderOtherNoiseSeeds) {
  for (const Spread& s : {kLab, kWide}) {
    const Rates r = alarmTrials(s);
    RecordProperty(s.wide_goal ? "false_alarm_wide" : "false_alarm_lab", std::to_string(r.rate()));
    std::printf("unchanged, unpaired (other noise seeds), %s spread: alarm in %d of %d trials\n",
                s.wide_goal ? "wide" : "lab", r.hits, r.trials);
    EXPECT_LE(r.rate(), 0.05);
  }
}

// The figures docs/ci.md quotes beyond the two requirements, printed; run with
// --gtest_also_run_disabled_tests --gtest_filter='*PowerTable*'.
TEST(TableComparison, DISABLED_PowerTable) {
  for (const Spread& s : {kLab, kWide}) {
    for (const bool paired : {true, false}) {
      for (const double f : {1.05, 1.1, 1.15, 1.2, 1.3, 1.5}) {
        const Rates r = plantedTrials(s, f, paired);
        std::printf("%s spread, %s, x%.2f: detected in %d of %d trials (%.1f %%)\n",
                    s.wide_goal ? "wide" : "lab", paired ? "paired" : "unpaired", f, r.hits,
                    r.trials, 100.0 * r.rate());
      }
    }
  }
}

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
  for (const World& world : kWorlds) EXPECT_TRUE(trackingFlagged(w, world.name)) << world.name;
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
