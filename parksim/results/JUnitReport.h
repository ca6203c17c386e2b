#pragma once
// JUnit XML, the test-report format CI systems show (GitLab's test reports, Jenkins' junit
// step, GitHub through its test-report actions). `parksim run --junit` writes one test case per
// realisation, `parksim sweep --junit` and `parksim report --junit` one per episode, `parksim
// compare --junit` one per compared metric (docs/ci.md).
//
// The document follows the schema Jenkins validates JUnit files against (the xunit plugin's
// junit-10.xsd: testsuites > testsuite > testcase with failure, skipped, system-out), with one
// extension that pytest, CTest and GoogleTest write too and readers that do not know it skip:
// <properties> inside a <testcase>, holding the episode's parameters. Times are durations in
// seconds (no time stamps), so a report differs between two runs only in its times.
//
// Every string may come from a user's file: it is escaped for XML (XmlText.h), so control
// characters and bytes that are not UTF-8 show as \xNN instead of breaking the document.

#include <optional>
#include <string>
#include <vector>

namespace parksim {

struct JUnitProperty {
  std::string name;
  std::string value;
};

/// Why a test case failed: `message` is the one line a CI page shows (the verdict's line), `type`
/// a short class (the verdict's status), `text` the details shown when it is opened.
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

/// The XML document (UTF-8, with the XML declaration and a final newline). Suite and report
/// attributes tests, failures, errors (always 0), skipped and time (the sum of their cases')
/// are counted from the cases.
std::string junitXml(const JUnitReport& report);

/// Writes junitXml(report) to `path` atomically. Throws Error when it cannot be written.
void writeJUnitFile(const std::string& path, const JUnitReport& report);

}  // namespace parksim
