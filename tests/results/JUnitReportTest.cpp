// The JUnit writer: counts, structure, durations, escaping. The schema check and a real
// consumer (junitparser) are in tests/sweep/test_junit_reports.py.

#include "parksim/results/reports/JUnitReport.h"

#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "parksim/pipeline/Verdict.h"

namespace parksim {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;

JUnitReport twoSuites() {
  JUnitCase ok{"seed=1",     "w / p / r",  1.25, {{"seed", "1"}},
               std::nullopt, std::nullopt, "",   std::nullopt};
  JUnitCase bad{"seed=2",
                "w / p / r",
                0.5,
                {{"seed", "2"}},
                JUnitFailure{"touched robot_5 at 17.829 s", "contact", "details\nmore"},
                std::nullopt,
                "",
                std::nullopt};
  JUnitCase skip{"p95", "other", 0.0, {}, std::nullopt, std::string("3 values"), "", std::nullopt};
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
  r.suites[0].cases.push_back({"a", "s", 1e-9, {}, std::nullopt, std::nullopt, "", std::nullopt});
  r.suites[0].cases.push_back({"b", "s", -3.0, {}, std::nullopt, std::nullopt, "", std::nullopt});
  r.suites[0].cases.push_back({"c", "s", NAN, {}, std::nullopt, std::nullopt, "", std::nullopt});
  r.suites[0].cases.push_back(
      {"d", "s", 12345.6789, {}, std::nullopt, std::nullopt, "", std::nullopt});
  const std::string xml = junitXml(r);
  EXPECT_THAT(xml, HasSubstr("name=\"a\" classname=\"s\" time=\"0.000\"/>"));
  EXPECT_THAT(xml, HasSubstr("name=\"b\" classname=\"s\" time=\"0.000\"/>"));
  EXPECT_THAT(xml, HasSubstr("name=\"c\" classname=\"s\" time=\"0.000\"/>"));
  EXPECT_THAT(xml, HasSubstr("name=\"d\" classname=\"s\" time=\"12345.679\"/>"));
  EXPECT_THAT(xml, Not(HasSubstr("e+")));
}

TEST(JUnitReport, UserTextIsEscapedEverywhere) {
  const std::string hostile = "w\x1b[2J<\"&>\xff\n";
  JUnitCase c{hostile,
              hostile,
              0.0,
              {{hostile, hostile}},
              JUnitFailure{hostile, hostile, hostile},
              std::nullopt,
              hostile,
              std::nullopt};
  const std::string xml = junitXml({hostile, {{hostile, {{hostile, hostile}}, {c}}}});
  EXPECT_THAT(xml, Not(HasSubstr("\x1b")));
  EXPECT_THAT(xml, Not(HasSubstr("\xff")));
  EXPECT_THAT(xml, Not(HasSubstr("<\"")));
  EXPECT_THAT(xml, HasSubstr("name=\"w\\x1b[2J&lt;&quot;&amp;&gt;\\xff&#10;\""));
  EXPECT_THAT(xml, HasSubstr("<system-out>w\\x1b[2J&lt;\"&amp;&gt;\\xff\n</system-out>"));
}

TEST(JUnitReport, SameReportSameBytes) { EXPECT_EQ(junitXml(twoSuites()), junitXml(twoSuites())); }

// Episode records as cases: every status the verdict can give, each where a CI page expects
// it. A user's planner or controller that failed is an error (the episode could not be
// judged), every other status but met a failure.
TEST(EpisodesJUnit, EveryStatusIsAPassAFailureOrAnErrorOfTheUsersCode) {
  std::vector<nlohmann::ordered_json> records;
  std::uint64_t seed = 0;
  for (const EpisodeStatus status : allEpisodeStatuses()) {
    nlohmann::ordered_json r;
    r["world"] = "lot";
    r["seed"] = ++seed;
    r["noise_seed"] = 1;
    r["status"] = toString(status);
    r["met_tolerance"] = status == EpisodeStatus::kMet;
    r["failure"] = status == EpisodeStatus::kMet ? "" : std::string("why ") + toString(status);
    records.push_back(r);
  }
  const JUnitReport report =
      episodesJUnit(records, "run", [](const nlohmann::ordered_json&) { return "suite"; });
  ASSERT_EQ(report.suites.size(), 1U);
  const std::vector<JUnitCase>& cases = report.suites[0].cases;
  ASSERT_EQ(cases.size(), allEpisodeStatuses().size());
  int errors = 0;
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const EpisodeStatus status = allEpisodeStatuses()[i];
    const JUnitCase& c = cases[i];
    EXPECT_EQ(c.name, "seed=" + std::to_string(i + 1) + " noise_seed=1");
    const bool user_code =
        status == EpisodeStatus::kPlannerError || status == EpisodeStatus::kControllerError;
    errors += user_code ? 1 : 0;
    EXPECT_EQ(c.error.has_value(), user_code) << toString(status);
    EXPECT_EQ(c.failure.has_value(), !user_code && status != EpisodeStatus::kMet)
        << toString(status);
    const std::optional<JUnitFailure>& why = user_code ? c.error : c.failure;
    if (why) {
      EXPECT_EQ(why->type, toString(status));
      EXPECT_EQ(why->message, std::string("why ") + toString(status));
    }
  }
  EXPECT_EQ(junitErrors(report), 2);
  EXPECT_EQ(junitFailures(report), static_cast<int>(cases.size()) - 1 - errors);
  const std::string xml = junitXml(report);
  EXPECT_THAT(xml, HasSubstr("errors=\"2\""));
  EXPECT_THAT(xml, HasSubstr("<error message=\"why planner_error\" type=\"planner_error\">"));
  EXPECT_THAT(xml, HasSubstr("<failure message=\"why plan_invalid\" type=\"plan_invalid\">"));
}

// A set: path is in the case's name and its properties, beside the schema's parameters.
TEST(EpisodesJUnit, SetValuesNameTheCaseAndAreProperties) {
  nlohmann::ordered_json r;
  r["episode_id"] = "0123456789abcdef";
  r["world"] = "lot";
  r["seed"] = 3;
  r["noise_seed"] = 2;
  r["sample"] = 4;
  r["robot.max_wheel_speed_radps"] = 6;
  r["planner.step_m"] = 0.05;
  r["status"] = "met";
  r["met_tolerance"] = true;
  r["max_pos_err_m"] = 0.001;  // a measurement: not a property
  const JUnitReport report =
      episodesJUnit({r}, "sweep", [](const nlohmann::ordered_json&) { return "s"; });
  const JUnitCase& c = report.suites.at(0).cases.at(0);
  EXPECT_EQ(c.name,
            "seed=3 noise_seed=2 sample=4 robot.max_wheel_speed_radps=6 planner.step_m=0.05 "
            "id=0123456789abcdef");
  std::vector<std::string> names;
  for (const JUnitProperty& p : c.properties) names.push_back(p.name);
  EXPECT_EQ(names,
            (std::vector<std::string>{"episode_id", "world", "seed", "noise_seed", "sample",
                                      "status", "robot.max_wheel_speed_radps", "planner.step_m"}));
  EXPECT_FALSE(c.failure || c.error);
}

}  // namespace
}  // namespace parksim
