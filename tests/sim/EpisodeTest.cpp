// Episodes on plans built in code: tracking, contacts, determinism, the observer.

#include "sim/Episode.h"

#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "core/Angle.h"
#include "sim/EpisodeFiles.h"
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

}  // namespace
}  // namespace parksim
