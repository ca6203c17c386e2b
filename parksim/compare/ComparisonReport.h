#pragma once
// A comparison (TableComparison.h) for people and CI pages: a Markdown summary (a CI job's
// summary page: GitHub's $GITHUB_STEP_SUMMARY, a GitLab merge-request note) and a JUnit report
// with one test suite per group and one test case per metric, failed where it regressed.

#include <string>

#include "parksim/compare/TableComparison.h"
#include "parksim/results/reports/JUnitReport.h"

namespace parksim {

/// What the reports say the tables were (paths as the user gave them).
struct ComparisonSources {
  std::string baseline;
  std::string candidate;
  int baseline_rows = 0;
  int candidate_rows = 0;
};

/// One line on one metric: "max tracking error p95: 1.862 -> 2.234 mm (+20.0 %, 95 % interval
/// +19.1 .. +21.0 %), Holm-adjusted p 0.0001", with the reason when it was not tested.
std::string metricLine(const MetricComparison& m, const CompareDef& def);

/// The Markdown summary: a headline (regression or not), the method's settings, one table row
/// per metric of every group, and the groups that are in one table only. Text from the tables
/// (world names) is escaped for Markdown table cells.
std::string comparisonMarkdown(const TableComparison& t, const CompareDef& def,
                               const ComparisonSources& sources);

/// The JUnit report: a suite per group (properties: pairing, rows on each side), a case per
/// metric, failed with metricLine when it regressed, skipped when it was not tested.
JUnitReport comparisonJUnit(const TableComparison& t, const CompareDef& def);

}  // namespace parksim
