// Episodes on plans built in code: tracking, contacts, determinism, the observer.

#include "parksim/sim/episode/Episode.h"

#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "parksim/core/geometry/Angle.h"
#include "parksim/core/io/Error.h"
#include "parksim/pipeline/Verdict.h"
#include "parksim/results/episode/ExecutedFile.h"
#include "parksim/results/episode/JsonFile.h"
#include "parksim/results/episode/MetricsFile.h"
#include "tests/sim/SimTestSupport.h"

namespace parksim {
namespace {

using testing::Segment;

// Forward arc, turn in place, reverse arc: every kind of motion a plan contains, within the
// robot's wheel speed and acceleration limits.
Trajectory manoeuvre(const Scenario& s) {
  std::vector<Segment> segs;
  auto add = [&](const std::vector<Segment>& more) {
    segs.insert(segs.end(), more.begin(), more.end());
  };
  add(testing::rampedSegments({6.0, 8.0}, 1.5, s.robot));
  add(testing::rampedSegments({-4.0, 4.0}, 0.8, s.robot));
  add(testing::rampedSegments({-7.0, -5.0}, 1.2, s.robot));
  return testing::planFromSegments(s.start, segs, s.robot);
}

void print(const char* what, const EpisodeMetrics& m) {
  std::printf(
      "%s: max %.4f mm rms %.4f mm final %.4f mm / %.4f deg, goal %.4f mm / %.4f deg, "
      "t %.3f s (plan %.3f), rest %d, contacts %d\n",
      what, m.max_pos_err_m * 1e3, m.rms_pos_err_m * 1e3, m.final_pos_err_m * 1e3,
      m.final_heading_err_deg, m.goal_pos_err_m * 1e3, m.goal_heading_err_deg, m.sim_time_s,
      m.plan_duration_s, m.ended_at_rest, m.contacts);
}

TEST(Episode, ClosedLoopTracksAHandMadePlanWithinAMillimetre) {
  Scenario s = testing::emptyLot({0.5, 0.5, 0.0});
  const Trajectory plan = manoeuvre(s);
  s.goal.pose = plan.points.back().pose;
  const EpisodeResult r = runEpisode(s, plan);
  print("closed", r.metrics);
  EXPECT_LT(r.metrics.max_pos_err_m, 0.001);
  EXPECT_LT(r.metrics.final_pos_err_m, 0.0005);
  EXPECT_LT(r.metrics.final_heading_err_deg, 0.2);
  EXPECT_TRUE(r.metrics.ended_at_rest);
  EXPECT_TRUE(r.metrics.goal_reached);
  EXPECT_EQ(r.metrics.contacts, 0);
}

TEST(Episode, EpisodesBeyondTheStepLimitAreRefusedBeforeTheWorldIsBuilt) {
  Scenario s = testing::emptyLot({0.5, 0.5, 0.0});
  const Trajectory plan = manoeuvre(s);
  const double steps = checkEpisodeLimits(s, plan);
  // The prediction: (plan + stop time) / time step, rounded up.
  EXPECT_EQ(
      steps,
      std::ceil((plan.duration() + ExecutionDef{}.max_stop_time_s) / s.physics.time_step_s - 1e-9));
  s.physics.time_step_s = 1e-9;
  EXPECT_THROW(checkEpisodeLimits(s, plan), Error);
  EXPECT_THROW(Episode(s, plan), Error);
  ExecutionDef def;
  def.max_steps = steps - 1;
  s.physics.time_step_s = 1.0 / 240.0;
  EXPECT_THROW(checkEpisodeLimits(s, plan, def), Error);
}

TEST(Episode, OpenLoopErrorsAreBounded) {
  Scenario s = testing::emptyLot({0.5, 0.5, 0.0});
  const Trajectory plan = manoeuvre(s);
  s.goal.pose = plan.points.back().pose;
  ExecutionDef def;
  def.tracking = TrackingMode::kOpen;
  const EpisodeResult r = runEpisode(s, plan, def);
  print("open", r.metrics);
  EXPECT_LT(r.metrics.max_pos_err_m, 0.010);
}

TEST(Episode, DrivingThroughAParkedRobotIsAContactWithItAndPushesIt) {
  Scenario s = testing::emptyLot({0.5, 0.5, 0.0});
  testing::addWall(s, "wall_far", 0.2, 0.9, 0.3, 1.0);
  // Straight ahead: the parked robot's rear edge is 50 mm in front of the ego's front edge.
  testing::addParkedRobot(s, "robot_ahead", {0.5 + 0.010 + 0.050 + 0.070, 0.5, 0.0});
  const Trajectory plan = testing::planFromSegments(
      s.start, testing::rampedSegments({5.0, 5.0}, 1.0, s.robot), s.robot);
  const EpisodeResult r = runEpisode(s, plan);
  print("through", r.metrics);
  // Pushed ahead, the box slides away and is caught up with again: a few events, all with it.
  ASSERT_GE(r.metrics.contacts, 1);
  EXPECT_EQ(r.metrics.first_contact_body, "robot_ahead");
  for (const ContactEvent& e : r.metrics.contact_events) EXPECT_EQ(e.body, "robot_ahead");
  EXPECT_EQ(r.metrics.contact_events.front().obstacle_index, 1);
  // 50 mm at 0.1 m/s after a 0.2 s ramp: first contact between 0.5 and 0.7 s.
  EXPECT_GT(r.metrics.first_contact_t_s, 0.5);
  EXPECT_LT(r.metrics.first_contact_t_s, 0.7);
  ASSERT_EQ(r.metrics.parked.size(), 1u);
  EXPECT_EQ(r.metrics.parked[0].name, "robot_ahead");
  // How far a pushed box slides is chaotic (7 to 49 mm under rounding-level changes of the
  // solver), so assert only that it clearly moved: unmoved robots stay below 0.1 mm.
  EXPECT_GT(r.metrics.parked[0].max_m, 0.002);
  EXPECT_FALSE(checkTracking(TrackingTolerance{}, r.metrics).empty());
}

TEST(Episode, DrivingIntoAWallIsAContactWithIt) {
  Scenario s = testing::emptyLot({0.5, 0.5, 0.0});
  testing::addWall(s, "wall_ahead", 0.54, 0.3, 0.64, 0.7);
  const Trajectory plan = testing::planFromSegments(
      s.start, testing::rampedSegments({4.0, 4.0}, 0.5, s.robot), s.robot);
  const EpisodeResult r = runEpisode(s, plan);
  print("wall", r.metrics);
  ASSERT_GE(r.metrics.contacts, 1);
  EXPECT_EQ(r.metrics.first_contact_body, "wall_ahead");
  EXPECT_GT(r.metrics.max_pos_err_m, 0.005);  // the wall stopped it
}

TEST(Episode, SameInputsGiveBitIdenticalExecutedCsv) {
  Scenario s = testing::emptyLot({0.5, 0.5, 0.0});
  testing::addParkedRobot(s, "robot_near", {0.9, 0.62, 0.0});
  const Trajectory plan = manoeuvre(s);
  for (TrackingMode mode : {TrackingMode::kClosed, TrackingMode::kOpen}) {
    ExecutionDef def;
    def.tracking = mode;
    const std::string first = executedCsv(runEpisode(s, plan, def).rows);
    const std::string second = executedCsv(runEpisode(s, plan, def).rows);
    EXPECT_GT(first.size(), 1000u);
    EXPECT_TRUE(first == second) << toString(mode);
  }
}

TEST(Episode, RowsAreTheSimulationRateWithTheExactPlanAsReference) {
  Scenario s = testing::emptyLot({0.5, 0.5, 0.0});
  const Trajectory plan = manoeuvre(s);
  const EpisodeResult r = runEpisode(s, plan);
  const double dt = s.physics.time_step_s;
  ASSERT_EQ(static_cast<long>(r.rows.size()), r.metrics.steps + 1);
  for (std::size_t k = 0; k < r.rows.size(); ++k) {
    ASSERT_EQ(r.rows[k].t_s, static_cast<double>(k) * dt);
  }
  // At every control period boundary the reference is the plan's point itself.
  for (std::size_t i = 0; i < plan.points.size(); ++i) {
    const auto k = static_cast<std::size_t>(std::lround(plan.points[i].t_s / dt));
    const Pose2& ref = r.rows[k].reference;
    EXPECT_NEAR(ref.x, plan.points[i].pose.x, 1e-12);
    EXPECT_NEAR(ref.y, plan.points[i].pose.y, 1e-12);
    EXPECT_NEAR(angleDiff(ref.theta, plan.points[i].pose.theta), 0.0, 1e-12);
  }
  // Open loop, the commands are exactly the plan's wheel speeds.
  ExecutionDef def;
  def.tracking = TrackingMode::kOpen;
  const EpisodeResult open = runEpisode(s, plan, def);
  for (std::size_t k = 1; k < open.rows.size(); ++k) {
    const double t_mid = open.rows[k].t_s - 0.5 * dt;
    const auto i = static_cast<std::size_t>(t_mid / 0.1);
    const WheelSpeeds expected = i + 1 < plan.points.size() ? plan.points[i].wheels : WheelSpeeds{};
    ASSERT_EQ(open.rows[k].wheels_cmd, expected) << "row " << k;
  }
}

TEST(Episode, ObserverGetsSamplesAtTheRequestedRate) {
  Scenario s = testing::emptyLot({0.5, 0.5, 0.0});
  testing::addParkedRobot(s, "robot_side", {0.5, 0.8, 0.0});
  const Trajectory plan = manoeuvre(s);
  std::vector<EpisodeSample> samples;
  const EpisodeResult r = runEpisode(
      s, plan, {}, [&](const EpisodeSample& x) { samples.push_back(x); }, 1.0 / 30.0);
  ASSERT_GE(samples.size(), 3u);
  EXPECT_EQ(samples.front().tracking.t_s, 0.0);
  EXPECT_EQ(samples.back().tracking.t_s, r.metrics.sim_time_s);
  for (std::size_t i = 1; i + 1 < samples.size(); ++i) {
    EXPECT_NEAR(samples[i].tracking.t_s, static_cast<double>(i) / 30.0, 1e-9);
    ASSERT_EQ(samples[i].obstacles.size(), 1u);
    EXPECT_NEAR(samples[i].obstacles[0].x, s.obstacles[0].box.center.x(), 1e-6);
  }
}

TEST(Episode, RejectsAnEmptyPlanAndABadDefinition) {
  const Scenario s = testing::emptyLot();
  EXPECT_THROW(Episode(s, Trajectory{}), Error);
  const Trajectory plan = testing::planFromSegments(s.start, {{{1.0, 1.0}, 0.2}}, s.robot);
  ExecutionDef def;
  def.csv_stride_steps = 0;
  EXPECT_THROW(Episode(s, plan, def), Error);
  Trajectory backwards = plan;
  backwards.points[1].t_s = 0.0;
  EXPECT_THROW(Episode(s, backwards), Error);
}

}  // namespace
}  // namespace parksim
