// The one verdict and the public tolerance helpers, on a metrics struct and on a metrics.json
// file.

#include "parksim/pipeline/Verdict.h"

#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "parksim/core/geometry/Angle.h"
#include "parksim/core/io/AtomicFile.h"
#include "parksim/core/io/Error.h"
#include "parksim/results/episode/JsonFile.h"
#include "parksim/results/episode/MetricsFile.h"
#include "tests/support/TestPaths.h"

namespace parksim {
namespace {

EpisodeMetrics goodMetrics() {
  EpisodeMetrics m;
  m.max_pos_err_m = 0.001;
  m.goal_pos_err_m = 0.001;
  m.goal_heading_err_deg = 0.5;
  m.goal_reached = true;
  return m;
}

std::string tempDir(const char* name) {
  const std::string dir = parksim::testing::binaryDir() + "/test-output/pipeline/" + name;
  std::filesystem::remove_all(dir);
  ensureDirectory(dir);
  return dir;
}

TEST(TrackingTolerance, PassesWithinEveryBound) {
  EXPECT_TRUE(checkTracking(TrackingTolerance{}, goodMetrics()).empty());
}

TEST(TrackingTolerance, NamesEveryViolatedBound) {
  EpisodeMetrics m = goodMetrics();
  m.max_pos_err_m = 0.0061;
  m.goal_heading_err_deg = 2.0;
  m.contacts = 2;
  m.first_contact_body = "robot_5";
  m.max_parked_displacement_m = 0.002;
  const std::vector<std::string> v = checkTracking(TrackingTolerance{}, m);
  ASSERT_EQ(v.size(), 4u) << joinViolations(v);
  EXPECT_EQ(v[0], "max_pos_err_m 0.0061 > 0.005");
  EXPECT_EQ(v[1], "goal_heading_err_deg 2 > 1.5");
  EXPECT_EQ(v[2], "contacts 2 > 0 (first: robot_5)");
  EXPECT_EQ(v[3], "max_parked_displacement_m 0.002 > 0.0001");
}

TEST(TrackingTolerance, NanFails) {
  EpisodeMetrics m = goodMetrics();
  m.goal_pos_err_m = std::nan("");
  EXPECT_EQ(checkTracking(TrackingTolerance{}, m).size(), 1u);
}

TEST(TrackingTolerance, GoalReachedIsOptional) {
  EpisodeMetrics m = goodMetrics();
  m.goal_reached = false;
  EXPECT_TRUE(checkTracking(TrackingTolerance{}, m).empty());
  TrackingTolerance strict;
  strict.require_goal_reached = true;
  EXPECT_EQ(checkTracking(strict, m), std::vector<std::string>{"goal_reached is false"});
}

TEST(TrackingTolerance, WorksOnAMetricsJsonFile) {
  const std::string dir = tempDir("tolerance");
  EpisodeMetrics m = goodMetrics();
  m.parked.push_back({"robot_3", 0.0, 0.0});
  writeJsonFile(dir + "/metrics.json", metricsToJson(m));
  EXPECT_TRUE(checkTrackingFile(TrackingTolerance{}, dir + "/metrics.json").empty());

  m.final_pos_err_m = 0.5;
  m.goal_pos_err_m = 0.004;
  writeJsonFile(dir + "/metrics.json", metricsToJson(m));
  EXPECT_EQ(checkTrackingFile(TrackingTolerance{}, dir + "/metrics.json"),
            std::vector<std::string>{"goal_pos_err_m 0.004 > 0.003"});

  const std::vector<std::string> missing = checkTrackingFile({}, dir + "/absent.json");
  ASSERT_EQ(missing.size(), 1u);
  EXPECT_NE(missing[0].find("cannot open"), std::string::npos);

  writeFileAtomically(dir + "/partial.json", "{\"max_pos_err_m\": 0.001}\n");
  const std::vector<std::string> partial = checkTrackingFile({}, dir + "/partial.json");
  ASSERT_EQ(partial.size(), 1u);
  EXPECT_NE(partial[0].find("missing key 'rms_pos_err_m'"), std::string::npos);
}

Scenario goalScenario() {
  Scenario s;
  s.goal.position_tolerance_m = 0.001;
  s.goal.heading_tolerance_rad = degToRad(0.5);
  return s;
}

TEST(Verdict, MetWithinEveryBoundAndTheGoal) {
  const Verdict v = judgeEpisode(goalScenario(), TrackingTolerance{}, goodMetrics());
  EXPECT_TRUE(v.met());
  EXPECT_EQ(v, Verdict{});
}

TEST(Verdict, ContactsAreJudgedAgainstMaxContactsFirst) {
  EpisodeMetrics m = goodMetrics();
  m.contacts = 1;
  m.first_contact_body = "robot_5";
  m.first_contact_t_s = 17.8294;
  m.goal_reached = false;  // a contact outranks a missed goal
  const Verdict v = judgeEpisode(goalScenario(), TrackingTolerance{}, m);
  EXPECT_EQ(v.status, EpisodeStatus::kContact);
  EXPECT_EQ(v.reason, "touched robot_5 at 17.829 s (1 contact event)");
  // Allowed contacts: the same episode is judged on the goal instead.
  TrackingTolerance lenient;
  lenient.max_contacts = 10;
  EXPECT_EQ(judgeEpisode(goalScenario(), lenient, m).status, EpisodeStatus::kGoalMissed);
  m.contacts = 11;
  EXPECT_EQ(judgeEpisode(goalScenario(), lenient, m).reason,
            "touched robot_5 at 17.829 s (11 contact events, at most 10)");
}

TEST(Verdict, AMissedGoalNamesTheDistanceAndTheTolerance) {
  EpisodeMetrics m = goodMetrics();
  m.goal_reached = false;
  m.goal_pos_err_m = 0.0012345;
  m.goal_heading_err_deg = 0.25;
  const Verdict v = judgeEpisode(goalScenario(), TrackingTolerance{}, m);
  EXPECT_EQ(v.status, EpisodeStatus::kGoalMissed);
  EXPECT_EQ(v.reason,
            "goal not reached: ended 1.234 mm / 0.250 deg from the goal (tolerance 1.000 mm / "
            "0.500 deg)");
}

TEST(Verdict, ABoundExceededIsToleranceMissedWithEveryViolation) {
  EpisodeMetrics m = goodMetrics();
  m.max_pos_err_m = 0.0061;
  m.max_parked_displacement_m = 0.002;
  const Verdict v = judgeEpisode(goalScenario(), TrackingTolerance{}, m);
  EXPECT_EQ(v.status, EpisodeStatus::kToleranceMissed);
  EXPECT_EQ(v.reason,
            "tracking tolerance not met: max_pos_err_m 0.0061 > 0.005; max_parked_displacement_m "
            "0.002 > 0.0001");
}

TEST(Verdict, AnUnsolvedPlanIsPlanFailed) {
  PlanResult plan;
  plan.status = PlanStatus::kIterationLimit;
  plan.message = "no path within 20 iterations";
  const Verdict v = planFailedVerdict(plan);
  EXPECT_EQ(v.status, EpisodeStatus::kPlanFailed);
  EXPECT_EQ(v.reason, "unsolved plan (iteration_limit): no path within 20 iterations");
}

TEST(Verdict, StatusNamesRoundTrip) {
  for (EpisodeStatus s : allEpisodeStatuses()) {
    EXPECT_EQ(episodeStatusFromString(toString(s)), s);
  }
  EXPECT_THROW((void)episodeStatusFromString("ok"), Error);
}

TEST(Verdict, RealisationsMeetTheirShareOrReportTheFirstFailure) {
  const Verdict contact{EpisodeStatus::kContact, "touched a"};
  const Verdict missed{EpisodeStatus::kGoalMissed, "goal not reached"};
  const std::vector<RealisationVerdict> rs = {{1, {}}, {2, contact}, {3, missed}, {4, {}}};
  EXPECT_EQ(judgeRealisations(rs, 1.0), contact);
  EXPECT_EQ(judgeRealisations(rs, 0.5), Verdict{});
  EXPECT_EQ(judgeRealisations(rs, 0.75), contact);
  // One realisation is judged exactly as the episode.
  EXPECT_EQ(judgeRealisations({{7, missed}}, 1.0), missed);
  EXPECT_EQ(judgeRealisations({{7, missed}}, 0.0), Verdict{});
  // 19 of 20 is 0.95 of them, whatever the rounding of 0.95 * 20.
  std::vector<RealisationVerdict> twenty(20, RealisationVerdict{0, {}});
  twenty[5].verdict = contact;
  EXPECT_TRUE(judgeRealisations(twenty, 0.95).met());
  EXPECT_THROW((void)judgeRealisations({}, 1.0), Error);
}

}  // namespace
}  // namespace parksim
