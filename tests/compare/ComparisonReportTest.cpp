// A comparison as Markdown (a CI job summary) and as JUnit: headline, one row per metric,
// escaped world names, failures where it regressed, skips where nothing was tested.

#include "parksim/compare/ComparisonReport.h"

#include <cmath>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace parksim {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;

TableComparison oneRegression() {
  MetricComparison rate{
      "success rate", "met_tolerance", -1.0, true, "", 20, 20, 20, 20, 1.0, 1.0, NAN, NAN, 1.0, 1.0,
      false};
  MetricComparison p95{"max tracking error p95",
                       "max_pos_err_m",
                       0.95,
                       true,
                       "",
                       20,
                       20,
                       0,
                       0,
                       1.862e-3,
                       2.234e-3,
                       0.19,
                       0.21,
                       9.999e-5,
                       4.9995e-4,
                       true};
  MetricComparison few{"goal error p95",
                       "goal_pos_err_m",
                       0.95,
                       false,
                       "3 values, fewer than 5",
                       3,
                       3,
                       0,
                       0,
                       0.0,
                       0.0,
                       0.0,
                       0.0,
                       1.0,
                       1.0,
                       false};
  GroupComparison g{"lot|a\x1b[1m", "hybrid-a-star", "lab", true, 20, 20, 20, {rate, p95, few}, {}};
  TableComparison t;
  t.groups = {g};
  t.only_candidate = {"corridor / rrt / lab"};
  t.tests = 2;
  t.regressions = 1;
  t.resamples = 10000;
  return t;
}

TEST(ComparisonReport, MetricLineSaysChangeIntervalAndAdjustedP) {
  const TableComparison t = oneRegression();
  EXPECT_EQ(metricLine(t.groups[0].metrics[1], CompareDef{}),
            "max tracking error p95: 1.862 mm -> 2.234 mm (+20.0 %, 95 % interval +19.0 % .. "
            "+21.0 %), Holm-adjusted p 0.0005 < 0.05: regression");
  EXPECT_EQ(metricLine(t.groups[0].metrics[0], CompareDef{}),
            "success rate: 20/20 -> 20/20 (+0.0 pp), Holm-adjusted p 1");
  EXPECT_EQ(metricLine(t.groups[0].metrics[2], CompareDef{}),
            "goal error p95: not tested (3 values, fewer than 5)");
}

TEST(ComparisonReport, MarkdownHasAHeadlineARowPerMetricAndEscapedNames) {
  const std::string md =
      comparisonMarkdown(oneRegression(), CompareDef{}, {"base|line", "cand", 20, 20});
  EXPECT_THAT(md, HasSubstr("## parksim compare: regression (1 of 2 tests)\n"));
  EXPECT_THAT(md, HasSubstr("Baseline `base\\|line` (20 episodes)"));
  EXPECT_THAT(md,
              HasSubstr("| lot\\|a\\x1b[1m / hybrid-a-star / lab | 20 paired | success rate |"));
  EXPECT_THAT(md, HasSubstr("| max tracking error p95 | 1.862 mm | 2.234 mm | +20.0 % | "
                            "+19.0 % .. +21.0 % | 0.0005 | **regression** |"));
  EXPECT_THAT(md, HasSubstr("| goal error p95 | - | - |  |  |  | not tested: 3 values, fewer "
                            "than 5 |"));
  EXPECT_THAT(md, HasSubstr("Only in the candidate (not compared): `corridor / rrt / lab`"));
  EXPECT_THAT(md, Not(HasSubstr("\x1b")));
}

TEST(ComparisonReport, JUnitFailsTheRegressionAndSkipsTheUntested) {
  const JUnitReport r = comparisonJUnit(oneRegression(), CompareDef{});
  ASSERT_EQ(r.suites.size(), 1u);
  ASSERT_EQ(r.suites[0].cases.size(), 3u);
  EXPECT_EQ(junitFailures(r), 1);
  EXPECT_FALSE(r.suites[0].cases[0].failure);
  ASSERT_TRUE(r.suites[0].cases[1].failure);
  EXPECT_THAT(r.suites[0].cases[1].failure->message, HasSubstr("regression"));
  EXPECT_EQ(r.suites[0].cases[2].skipped, std::optional<std::string>("3 values, fewer than 5"));
}

// Compared across the planner: the summary says so, each group shows what each side ran, and
// the JUnit suite holds both sides' values; without --across none of it appears.
TEST(ComparisonReport, AcrossColumnsAreNamedWithEachSidesValues) {
  TableComparison t = oneRegression();
  EXPECT_THAT(comparisonMarkdown(t, CompareDef{}, {"b", "c", 20, 20}),
              Not(HasSubstr("Compared across")));
  t.across = {"planner"};
  t.groups[0].planner = "*";
  t.groups[0].across = {{"planner", "time-a-star", "example"}};
  const std::string md = comparisonMarkdown(t, CompareDef{}, {"b", "c", 20, 20});
  EXPECT_THAT(md, HasSubstr("\n\nCompared across `planner`: the tables may differ in it; rows "
                            "pair when every other parameter is equal, and a group's name shows "
                            "the planner as `*`.\n\n| group |"));
  EXPECT_THAT(md, HasSubstr("| lot\\|a\\x1b[1m / * / lab (planner: time-a-star vs example) | "
                            "20 paired | success rate |"));
  const JUnitReport r = comparisonJUnit(t, CompareDef{});
  EXPECT_EQ(r.suites[0].name, "lot|a\x1b[1m / * / lab");
  const auto property = [&](const std::string& name) {
    for (const JUnitProperty& p : r.suites[0].properties) {
      if (p.name == name) return p.value;
    }
    return std::string("(missing)");
  };
  EXPECT_EQ(property("baseline.planner"), "time-a-star");
  EXPECT_EQ(property("candidate.planner"), "example");
}

}  // namespace
}  // namespace parksim
