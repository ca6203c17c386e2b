// The JUnit writer: counts, structure, durations, escaping. The schema check and a real
// consumer (junitparser) are in tests/sweep/test_junit_reports.py.

#include "parksim/results/JUnitReport.h"

#include <cmath>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace parksim {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;

JUnitReport twoSuites() {
  JUnitCase ok{"seed=1", "w / p / r", 1.25, {{"seed", "1"}}, std::nullopt, std::nullopt, ""};
  JUnitCase bad{"seed=2",
                "w / p / r",
                0.5,
                {{"seed", "2"}},
                JUnitFailure{"touched robot_5 at 17.829 s", "contact", "details\nmore"},
                std::nullopt,
                ""};
  JUnitCase skip{"p95", "other", 0.0, {}, std::nullopt, std::string("3 values"), ""};
  return {"sweep", {{"w / p / r", {{"sha", "abc"}}, {ok, bad}}, {"other", {}, {skip}}}};
}

TEST(JUnitReport, CountsTestsFailuresAndSkipsPerSuiteAndInTotal) {
  const std::string xml = junitXml(twoSuites());
  EXPECT_THAT(xml, HasSubstr("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"));
  EXPECT_THAT(xml, HasSubstr("<testsuites name=\"sweep\" tests=\"3\" failures=\"1\" "
                             "errors=\"0\" time=\"1.750\">"));
  EXPECT_THAT(xml, HasSubstr("<testsuite name=\"w / p / r\" tests=\"2\" failures=\"1\" "
                             "errors=\"0\" skipped=\"0\" time=\"1.750\">"));
  EXPECT_THAT(xml, HasSubstr("<testsuite name=\"other\" tests=\"1\" failures=\"0\" errors=\"0\" "
                             "skipped=\"1\" time=\"0.000\">"));
  EXPECT_EQ(junitFailures(twoSuites()), 1);
}

TEST(JUnitReport, FailureCarriesTheLineAsMessageAndTheStatusAsType) {
  const std::string xml = junitXml(twoSuites());
  EXPECT_THAT(xml, HasSubstr("<failure message=\"touched robot_5 at 17.829 s\" "
                             "type=\"contact\">details\nmore</failure>"));
  EXPECT_THAT(xml, HasSubstr("<skipped message=\"3 values\"/>"));
  EXPECT_THAT(xml, HasSubstr("<property name=\"seed\" value=\"2\"/>"));
  EXPECT_THAT(xml, HasSubstr("<property name=\"sha\" value=\"abc\"/>"));
}

TEST(JUnitReport, TimesAreDurationsWithoutExponentOrSign) {
  JUnitReport r{"t", {{"s", {}, {}}}};
  r.suites[0].cases.push_back({"a", "s", 1e-9, {}, std::nullopt, std::nullopt, ""});
  r.suites[0].cases.push_back({"b", "s", -3.0, {}, std::nullopt, std::nullopt, ""});
  r.suites[0].cases.push_back({"c", "s", NAN, {}, std::nullopt, std::nullopt, ""});
  r.suites[0].cases.push_back({"d", "s", 12345.6789, {}, std::nullopt, std::nullopt, ""});
  const std::string xml = junitXml(r);
  EXPECT_THAT(xml, HasSubstr("name=\"a\" classname=\"s\" time=\"0.000\"/>"));
  EXPECT_THAT(xml, HasSubstr("name=\"b\" classname=\"s\" time=\"0.000\"/>"));
  EXPECT_THAT(xml, HasSubstr("name=\"c\" classname=\"s\" time=\"0.000\"/>"));
  EXPECT_THAT(xml, HasSubstr("name=\"d\" classname=\"s\" time=\"12345.679\"/>"));
  EXPECT_THAT(xml, Not(HasSubstr("e+")));
}

TEST(JUnitReport, UserTextIsEscapedEverywhere) {
  const std::string hostile = "w\x1b[2J<\"&>\xff\n";
  JUnitCase c{
      hostile,      hostile, 0.0, {{hostile, hostile}}, JUnitFailure{hostile, hostile, hostile},
      std::nullopt, hostile};
  const std::string xml = junitXml({hostile, {{hostile, {{hostile, hostile}}, {c}}}});
  EXPECT_THAT(xml, Not(HasSubstr("\x1b")));
  EXPECT_THAT(xml, Not(HasSubstr("\xff")));
  EXPECT_THAT(xml, Not(HasSubstr("<\"")));
  EXPECT_THAT(xml, HasSubstr("name=\"w\\x1b[2J&lt;&quot;&amp;&gt;\\xff&#10;\""));
  EXPECT_THAT(xml, HasSubstr("<system-out>w\\x1b[2J&lt;\"&amp;&gt;\\xff\n</system-out>"));
}

TEST(JUnitReport, SameReportSameBytes) { EXPECT_EQ(junitXml(twoSuites()), junitXml(twoSuites())); }

}  // namespace
}  // namespace parksim
