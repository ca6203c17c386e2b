#pragma once
// `parksim compare BASELINE CANDIDATE`: did the candidate get worse than the baseline? Two
// results tables (sweeps of the same spec before and after a change) are grouped as `parksim
// report` groups them (world x planner configuration x realism), and in each group that both
// hold, five things are tested for a regression:
//
//   success rate (met_tolerance)      exact test: McNemar paired, Fisher unpaired (ExactTest.h)
//   max tracking error median, p95    bootstrap of the quantile's change (Bootstrap.h)
//   goal error median, p95            (max_pos_err_m, goal_pos_err_m)
//
// Pairing: a group is paired when both tables hold exactly the same episode ids in it (ids
// spell every parameter, so the same spec gives the same ids); then episodes are matched by
// id, and the test sees each episode's own change. Otherwise (other noise seeds, other planner
// seeds: other ids) the two samples are compared as independent samples. Tables that differ by
// design in the planner or the controller are compared across those columns (CompareDef::
// across): groups are keyed and rows paired without them (RowPairing.h).
//
// A quantile is a regression when it grew by more than the relative margin (max_increase) and
// the absolute one (min_increase_m): the hypothesis tested is "excess <= 0" with excess =
// q_candidate - max((1 + r) q_baseline, q_baseline + a), and its p-value is the share of
// bootstrap replicates with excess <= 0 (one added above and below: (1 + k) / (B + 1)). The
// success rate is a regression when the exact test finds it lower and it dropped by more than
// max_success_drop. Every p-value of every group is then adjusted by Holm's method
// (HolmCorrection.h), and a test is a regression when its adjusted p-value is below
// 1 - confidence: unchanged code raises no alarm anywhere with probability at least
// `confidence`. Only increases of errors and drops of the success rate count; improvements
// are reported, never alarmed. docs/ci.md has the method and its measured power.
//
// Deterministic: each test draws its bootstrap from its own generator, seeded by `seed` and
// the test's group and metric, so the same tables and seed give the same numbers, and adding a
// group to the tables does not change another group's.

#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace parksim {

struct CompareDef {
  /// Family-wise confidence, in (0, 1): unchanged code raises no alarm in any group or metric
  /// with at least this probability (Holm's correction over every test).
  double confidence = 0.95;
  /// An error quantile must grow by more than this share of the baseline's, 0..10 ...
  double max_increase = 0.10;
  /// ... and by more than this, m (0.01 mm: below what a change of the code means).
  double min_increase_m = 1e-5;
  /// The success rate must drop by more than this share, 0..1 (0: any significant drop).
  double max_success_drop = 0.0;
  /// Bootstrap replicates per quantile test; raised to 2 m / (1 - confidence) for m tests,
  /// so the smallest p-value can pass Holm's correction.
  int resamples = 10000;
  /// Seeds the bootstrap.
  std::uint64_t seed = 1;
  /// A group with fewer values than this on either side has its quantiles not tested.
  int min_samples = 5;
  /// Parameter columns the two tables differ in by design: planner, controller, planner.NAME,
  /// controller.NAME. Groups are keyed and rows paired without them (RowPairing.h); empty:
  /// groups as `parksim report`'s, rows paired by episode id.
  std::vector<std::string> across;
};

/// One tested (or untested) quantity of one group.
struct MetricComparison {
  std::string name;  ///< "success rate", "max tracking error median", "goal error p95", ...
  std::string key;   ///< the results column: met_tolerance, max_pos_err_m, goal_pos_err_m
  double q = -1.0;   ///< the quantile compared, -1 for the success rate
  bool tested = false;
  std::string note;    ///< why it was not tested, else empty
  int baseline_n = 0;  ///< values (episodes) on each side; pairs when paired
  int candidate_n = 0;
  int baseline_met = 0;  ///< success rate: episodes that met their tolerance
  int candidate_met = 0;
  /// The statistic on each side: a rate in 0..1 or a quantile in m.
  double baseline = 0.0;
  double candidate = 0.0;
  /// Quantiles: percentile bootstrap interval of the relative change candidate / baseline - 1 at
  /// `confidence` (not adjusted for many tests); NaN for the success rate.
  double ci_low = 0.0;
  double ci_high = 0.0;
  double p = 1.0;           ///< one-sided p-value of the test
  double p_adjusted = 1.0;  ///< Holm-adjusted over every test
  bool regression = false;
};

/// The values one group's rows hold in a column compared across, on each side.
struct AcrossValues {
  std::string column;
  std::string baseline;  ///< the distinct values (RowPairing::valueText), sorted, ", "-separated
  std::string candidate;
};

struct GroupComparison {
  std::string world;
  std::string planner;  ///< plannerLabel; its planner "*" when compared across the planner
  std::string realism;
  bool paired = false;
  int shared_ids = 0;  ///< episodes in both tables: by id, or by RowPairing::pairKey across
  int baseline_rows = 0;
  int candidate_rows = 0;
  std::vector<MetricComparison> metrics;
  std::vector<AcrossValues> across;  ///< one per CompareDef::across column, in its order

  /// "<world> / <planner> / <realism>", as `parksim report` and the JUnit suites name groups.
  std::string name() const;
};

struct TableComparison {
  std::vector<GroupComparison> groups;      ///< groups in both tables, sorted by name
  std::vector<std::string> only_baseline;   ///< group names found in the baseline alone
  std::vector<std::string> only_candidate;  ///< ... in the candidate alone
  int tests = 0;                            ///< tests run (Holm's m)
  int regressions = 0;                      ///< tests that found a regression
  int resamples = 0;                        ///< bootstrap replicates used per quantile test
  std::vector<std::string> across;          ///< the columns compared across (CompareDef)

  bool regression() const { return regressions > 0; }
};

/// Throws Error when a setting is out of range.
void checkCompareDef(const CompareDef& def);

/// Compares two tables' rows (readResultsJsonl). Throws Error when a table is empty, holds an
/// episode id twice (across columns: two rows that differ only in them), no group is in both,
/// or neither table has a column compared across.
TableComparison compareTables(const std::vector<nlohmann::ordered_json>& baseline,
                              const std::vector<nlohmann::ordered_json>& candidate,
                              const CompareDef& def);

}  // namespace parksim
