// The public tolerance helper, on a metrics struct and on a metrics.json file; the files'
// formats.

#include "parksim/sim/TrackingTolerance.h"

#include <filesystem>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

#include "parksim/core/AtomicFile.h"
#include "parksim/sim/EpisodeFiles.h"
#include "parksim/sim/ReferenceTrajectory.h"
#include "parksim/sim/TrackingController.h"
#include "tests/sim/SimTestSupport.h"
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
  const std::string dir = parksim::testing::binaryDir() + "/test-output/sim/" + name;
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

TEST(EpisodeFiles, MetricsJsonHasTheFlatKeys) {
  EpisodeMetrics m = goodMetrics();
  m.parked.push_back({"robot_3", 1e-5, 0.0});
  m.contact_events.push_back({0.5, 2, "wall_1"});
  m.contact_events.push_back({0.9, 2, "wall_1"});
  m.contacts = 2;
  const nlohmann::json j = metricsToJson(m);
  for (const char* key :
       {"max_pos_err_m", "rms_pos_err_m", "final_pos_err_m", "final_heading_err_deg", "contacts",
        "goal_reached", "sim_time_s", "wall_time_s", "goal_pos_err_m", "goal_heading_err_deg",
        "max_parked_displacement_m", "tracking", "parked_displacement_m.robot_3"}) {
    EXPECT_TRUE(j.contains(key)) << key;
  }
  for (const auto& [key, value] : j.items()) {
    if (key == "contact_bodies") continue;
    EXPECT_TRUE(value.is_primitive()) << key;
  }
  EXPECT_EQ(j["contact_bodies"], nlohmann::json::array({"wall_1"}));
  EXPECT_EQ(j["tracking"], "closed");
  const EpisodeMetrics back = metricsFromJson(j);
  EXPECT_EQ(back.max_pos_err_m, m.max_pos_err_m);
  EXPECT_EQ(back.contacts, 2);
}

TEST(EpisodeFiles, ExecutedCsvHeaderAndRoundTripPrecision) {
  ExecutedRow row;
  row.t_s = 1.0 / 240.0;
  row.pose = {0.1, 1.0 / 3.0, -2.0 / 7.0};
  row.pos_err_m = 1e-17;
  const std::string csv = executedCsv({row});
  std::istringstream in(csv);
  std::string header, line;
  std::getline(in, header);
  std::getline(in, line);
  EXPECT_EQ(header,
            "t,x,y,theta,x_ref,y_ref,theta_ref,omega_left_cmd,omega_right_cmd,omega_left,"
            "omega_right,pos_err,heading_err");
  std::istringstream cells(line);
  std::string cell;
  std::vector<double> values;
  while (std::getline(cells, cell, ',')) values.push_back(std::stod(cell));
  ASSERT_EQ(values.size(), 13u);
  EXPECT_EQ(values[0], row.t_s);
  EXPECT_EQ(values[2], row.pose.y);
  EXPECT_EQ(values[3], row.pose.theta);
  EXPECT_EQ(values[11], row.pos_err_m);
}

TEST(ReferenceTrajectory, InterpolatesExactlyAndHoldsTheEnds) {
  const RobotDef robot;
  const Trajectory plan =
      testing::planFromSegments({0.2, 0.3, 0.4}, {{{3.0, 5.0}, 0.3}, {{-2.0, 2.0}, 0.2}}, robot);
  const ReferenceTrajectory ref(plan, robot);
  EXPECT_EQ(ref.poseAt(-1.0), plan.points.front().pose);
  EXPECT_EQ(ref.poseAt(99.0), plan.points.back().pose);
  EXPECT_EQ(ref.wheelsAt(99.0), WheelSpeeds{});
  EXPECT_EQ(ref.wheelsAt(0.25), (WheelSpeeds{3.0, 5.0}));
  EXPECT_EQ(ref.wheelsAt(0.35), (WheelSpeeds{-2.0, 2.0}));
  const Pose2 mid = ref.poseAt(0.137);
  const Pose2 expected = integrateExact(plan.points[1].pose, toTwist({3.0, 5.0}, robot), 0.037);
  EXPECT_EQ(mid, expected);
  EXPECT_EQ(ref.poseAt(plan.points[2].t_s), plan.points[2].pose);
}

TEST(TrackingController, NoErrorGivesTheFeedForward) {
  const RobotDef robot;
  const Pose2 p{0.5, 0.5, 1.0};
  const Twist ff{0.05, 0.3};
  const WheelSpeeds w = trackingCommand(p, p, ff, TrackingGains{}, robot);
  const WheelSpeeds expected = toWheelSpeeds(ff, robot);
  EXPECT_NEAR(w.left_radps, expected.left_radps, 1e-12);
  EXPECT_NEAR(w.right_radps, expected.right_radps, 1e-12);
}

TEST(TrackingController, CorrectsTowardsTheReferenceAndRespectsTheWheelLimit) {
  const RobotDef robot;
  const Pose2 actual{0.0, 0.0, 0.0};
  // Reference ahead: faster. Reference to the left while moving forward: turn left.
  const Twist ahead = toTwist(trackingCommand(actual, {0.001, 0, 0}, {0.05, 0}, {}, robot), robot);
  EXPECT_GT(ahead.v_mps, 0.05);
  const Twist left = toTwist(trackingCommand(actual, {0, 0.001, 0}, {0.05, 0}, {}, robot), robot);
  EXPECT_GT(left.omega_radps, 0.0);
  // Reversing with the reference to the left: the heading must turn the other way.
  const Twist back = toTwist(trackingCommand(actual, {0, 0.001, 0}, {-0.05, 0}, {}, robot), robot);
  EXPECT_LT(back.omega_radps, 0.0);
  const WheelSpeeds big = trackingCommand(actual, {1.0, 0, 0}, {0.19, 0.0}, {}, robot);
  EXPECT_LE(std::max(std::abs(big.left_radps), std::abs(big.right_radps)),
            robot.max_wheel_speed_radps + 1e-12);
  const WheelSpeeds scaled = limitWheelSpeeds({20.0, 10.0}, robot);
  EXPECT_EQ(scaled, (WheelSpeeds{10.0, 5.0}));
}

}  // namespace
}  // namespace parksim
