#pragma once
// JUnit XML, the test-report format CI systems show (GitLab's test reports, Jenkins' junit
// step, GitHub through its test-report actions): parksim's one JUnit writer. Episodes become
// test cases through episodesJUnit, from their records (EpisodeRecord.h): `parksim run --junit`
// one per realisation, `parksim sweep --junit` and `parksim report --junit` one per episode of
// the results table; `parksim compare --junit` writes one case per compared metric
// (compare/ComparisonReport.h) through the same document model (docs/ci.md).
//
// The document follows the schema Jenkins validates JUnit files against (the xunit plugin's
// junit-10.xsd: testsuites > testsuite > testcase with failure, error, skipped, system-out),
// with one extension that pytest, CTest and GoogleTest write too and readers that do not know
// it skip: <properties> inside a <testcase>, holding the episode's parameters. Times are
// durations in seconds (no time stamps), so a report differs between two runs only in its
// times.
//
// Every string may come from a user's file: it is escaped for XML (XmlText.h), so control
// characters and bytes that are not UTF-8 show as \xNN instead of breaking the document.

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace parksim {

struct JUnitProperty {
  std::string name;
  std::string value;
};

/// Why a test case failed (or erred): `message` is the one line a CI page shows (the verdict's
/// line), `type` a short class (the verdict's status), `text` the details shown when it is
/// opened.
struct JUnitFailure {
  std::string message;
  std::string type;
  std::string text;
};

struct JUnitCase {
  std::string name;
  std::string classname;
  double time_s = 0.0;  ///< duration, s (negative or not finite: written as 0)
  std::vector<JUnitProperty> properties;
  std::optional<JUnitFailure> failure;
  /// Set: the case was not run (e.g. not enough data to compare); its value says why.
  std::optional<std::string> skipped;
  std::string system_out;  ///< written as <system-out> when not empty
  /// Set: the case could not be judged because code under test failed (a user's planner or
  /// controller threw, crashed or timed out): written as <error>, counted as an error.
  std::optional<JUnitFailure> error;
};

struct JUnitSuite {
  std::string name;
  std::vector<JUnitProperty> properties;
  std::vector<JUnitCase> cases;
};

struct JUnitReport {
  std::string name;
  std::vector<JUnitSuite> suites;
};

/// Test cases with a failure, over the whole report.
int junitFailures(const JUnitReport& report);
/// Test cases with an error, over the whole report.
int junitErrors(const JUnitReport& report);

/// The XML document (UTF-8, with the XML declaration and a final newline). Suite and report
/// attributes tests, failures, errors, skipped and time (the sum of their cases') are counted
/// from the cases.
std::string junitXml(const JUnitReport& report);

/// Writes junitXml(report) to `path` atomically. Throws Error when it cannot be written.
void writeJUnitFile(const std::string& path, const JUnitReport& report);

/// The suite a record belongs to, by its name (report/Report.h's rowGroupName: "<world> /
/// <planner configuration> / <realism>").
using RecordSuite = std::function<std::string(const nlohmann::ordered_json&)>;

/// Episode records (results-table rows, or a run's realisations as records) as a JUnit report
/// named `name`: one suite per `suite_of` name, sorted; in each, one case per record, sorted by
/// seed, noise seed, sample and episode id, named by them ("seed=S noise_seed=N", then
/// " start=dx,dy,dyaw" and " goal=..." when offset, " sample=K", each set key " path=value",
/// " id=<episode id>" when the record has one). Its properties: the record's JUnit fields
/// (EpisodeRecord.h: episode_id, the parameters, status) and its set keys. A record that did
/// not meet its tolerance fails with its `failure` line as the message and its `status` as the
/// type; planner_error and controller_error are errors of the user's code, written as <error>.
/// Time: the record's episode_wall_s, else its sim_wall_s.
JUnitReport episodesJUnit(const std::vector<nlohmann::ordered_json>& records,
                          const std::string& name, const RecordSuite& suite_of);

}  // namespace parksim
