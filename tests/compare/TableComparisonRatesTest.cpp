// `parksim compare`'s power and false-alarm rates on tables with known truth, written through the
// results-table writer and read back as the command reads them (issue 20's done-when):
// - power: every tracking error of one group multiplied by 1.2, 20 paired realisations per
//   group: detected in >= 90 % of seeded trials;
// - false alarms: the same code under other noise seeds (other ids: unpaired): no alarm in
//   >= 95 % of trials.
// One trial is one pair of tables (tests/compare/SyntheticTables.h). A rate over 200 trials is
// the assertion, so the program runs once, in the Release pass of scripts/test.sh (RELEASE in
// tests/compare/CMakeLists.txt): under the sanitizers it took 70 s. The comparison's code runs
// under the sanitizers in compare_tests.

#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "parksim/compare/TableComparison.h"
#include "tests/compare/SyntheticTables.h"

namespace parksim {
namespace {

using synthetic::Json;
using synthetic::kLab;
using synthetic::kWide;
using synthetic::Spread;
using synthetic::syntheticTable;
using synthetic::throughTheWriter;
using synthetic::trackingFlagged;

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

}  // namespace
}  // namespace parksim
