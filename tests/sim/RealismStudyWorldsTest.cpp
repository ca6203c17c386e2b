// The realism presets on the study's worlds: `ideal` is today's model exactly, `lab` tracks
// within a documented band that is clearly above ideal (so a tolerance can fail), open loop is
// clearly worse, results do not depend on where the lot lies, and parked robots far away
// change nothing. Few noise seeds, to stay fast; `parksim run --realisations` does many.

#include <cstdio>
#include <map>
#include <string>

#include <gtest/gtest.h>

#include "parksim/collision/BulletCollisionWorld.h"
#include "parksim/planner/base/PlanScenario.h"
#include "parksim/results/episode/ExecutedFile.h"
#include "parksim/results/episode/JsonFile.h"
#include "parksim/results/episode/MetricsFile.h"
#include "parksim/scenario/world/ScenarioReader.h"
#include "parksim/sim/episode/Episode.h"
#include "tests/sim/SimTestSupport.h"
#include "tests/support/TestPaths.h"

namespace parksim {
namespace {

struct Planned {
  Scenario scenario;
  Trajectory plan;
};

const Planned& planned(const std::string& world) {
  static std::map<std::string, Planned> cache;
  auto it = cache.find(world);
  if (it == cache.end()) {
    Planned p;
    p.scenario = loadScenario(parksim::testing::sourceDir() + "/worlds/" + world + ".yaml");
    const BulletCollisionWorld checker(p.scenario);
    PlanSetup setup;
    setup.search.seed = 1;
    setup.search.record_tree = false;
    const PlanResult result = planScenario(p.scenario, checker, setup);
    EXPECT_TRUE(result.solved()) << result.message;
    p.plan = result.trajectory;
    it = cache.emplace(world, std::move(p)).first;
  }
  return it->second;
}

ExecutionDef withRealism(const std::string& preset, std::uint64_t noise_seed,
                         TrackingMode mode = TrackingMode::kClosed) {
  ExecutionDef e;
  e.tracking = mode;
  e.realism = presetRealism(preset);
  e.noise_seed = noise_seed;
  return e;
}

class RealismWorlds : public ::testing::TestWithParam<const char*> {};

TEST_P(RealismWorlds, IdealPresetIsTodaysModelByteForByte) {
  const Planned& p = planned(GetParam());
  const EpisodeResult plain = runEpisode(p.scenario, p.plan, ExecutionDef{});
  const EpisodeResult ideal = runEpisode(p.scenario, p.plan, withRealism("ideal", 7));
  EXPECT_EQ(executedCsv(plain.rows), executedCsv(ideal.rows));
  // Today's 13 columns, and the estimate is the truth.
  const std::string csv = executedCsv(ideal.rows, ideal.metrics.realism != "ideal");
  EXPECT_EQ(csv.substr(0, csv.find('\n')),
            "t,x,y,theta,x_ref,y_ref,theta_ref,omega_left_cmd,omega_right_cmd,omega_left,"
            "omega_right,pos_err,heading_err");
  EXPECT_EQ(ideal.metrics.max_est_pos_err_m, 0.0);
}

// Band (docs/realism.md): ideal tracks within ~0.7 mm on these worlds; lab, with 50-75 ms
// motor lag, 50 Hz control and 0.5 mm mocap noise, is predicted to lag by a few millimetres
// at the plans' wheel-speed steps. Above 1 mm and above 1.3x ideal (a 1 mm tolerance fails),
// below 10 mm (the loop still works), goal reached, no contact.
TEST_P(RealismWorlds, LabClosedLoopTracksWithinItsBandOverSeveralNoiseSeeds) {
  const Planned& p = planned(GetParam());
  const EpisodeMetrics ideal = runEpisode(p.scenario, p.plan, ExecutionDef{}).metrics;
  double worst = 0.0;
  double worst_goal = 0.0;
  for (std::uint64_t seed : {1, 2, 3}) {
    const EpisodeMetrics m = runEpisode(p.scenario, p.plan, withRealism("lab", seed)).metrics;
    std::printf(
        "%s lab seed %llu: max %.3f mm, goal %.3f mm / %.3f deg, est max %.3f mm, slip "
        "max %.1f mm/s, ideal max %.3f mm\n",
        GetParam(), static_cast<unsigned long long>(seed), m.max_pos_err_m * 1e3,
        m.goal_pos_err_m * 1e3, m.goal_heading_err_deg, m.max_est_pos_err_m * 1e3,
        m.max_slip_mps * 1e3, ideal.max_pos_err_m * 1e3);
    EXPECT_TRUE(m.goal_reached) << seed;
    EXPECT_EQ(m.contacts, 0) << seed;
    EXPECT_GT(m.max_pos_err_m, 1e-3) << seed;
    EXPECT_GT(m.max_pos_err_m, 1.3 * ideal.max_pos_err_m) << seed;
    EXPECT_LT(m.max_pos_err_m, 10e-3) << seed;
    EXPECT_GT(m.max_est_pos_err_m, 0.0) << seed;
    EXPECT_LT(m.max_est_pos_err_m, 3e-3) << seed;
    worst = std::max(worst, m.max_pos_err_m);
    worst_goal = std::max(worst_goal, m.goal_pos_err_m);
  }
  const EpisodeMetrics open =
      runEpisode(p.scenario, p.plan, withRealism("lab", 1, TrackingMode::kOpen)).metrics;
  std::printf("%s lab open loop: max %.3f mm, goal %.3f mm\n", GetParam(), open.max_pos_err_m * 1e3,
              open.goal_pos_err_m * 1e3);
  // Open loop has the motors' own speed loops but nothing that sees the pose.
  EXPECT_GT(open.max_pos_err_m, 1.5 * worst);
  EXPECT_GT(open.goal_pos_err_m, 2.0 * worst_goal);
  EXPECT_FALSE(open.goal_reached);
}

TEST_P(RealismWorlds, SameSeedsAreBitIdenticalAndNoiseSeedsDiffer) {
  const Planned& p = planned(GetParam());
  const EpisodeResult a = runEpisode(p.scenario, p.plan, withRealism("lab", 5));
  const EpisodeResult b = runEpisode(p.scenario, p.plan, withRealism("lab", 5));
  const EpisodeResult c = runEpisode(p.scenario, p.plan, withRealism("lab", 6));
  EXPECT_EQ(executedCsv(a.rows, true), executedCsv(b.rows, true));
  EXPECT_EQ(sensorsCsv(a.pose_samples, a.metrics.time_step_s),
            sensorsCsv(b.pose_samples, b.metrics.time_step_s));
  EXPECT_NE(executedCsv(a.rows, true), executedCsv(c.rows, true));
  EXPECT_NE(a.metrics.true_left_radius_m, c.metrics.true_left_radius_m);
}

Scenario shifted(const Scenario& s, double dx, double dy) {
  Scenario out = s;
  out.lot = {s.lot.x_min_m + dx, s.lot.y_min_m + dy, s.lot.x_max_m + dx, s.lot.y_max_m + dy};
  for (Obstacle& o : out.obstacles) o.box.center += Eigen::Vector2d(dx, dy);
  out.start.x += dx;
  out.start.y += dy;
  out.goal.pose.x += dx;
  out.goal.pose.y += dy;
  return out;
}

Trajectory shifted(const Trajectory& t, double dx, double dy) {
  Trajectory out = t;
  for (TrajectoryPoint& p : out.points) {
    p.pose.x += dx;
    p.pose.y += dy;
  }
  return out;
}

TEST_P(RealismWorlds, TheLotTracksTheSameTenKilometresAway) {
  const Planned& p = planned(GetParam());
  const double d = 10000.0;
  const Scenario far = shifted(p.scenario, d, d);
  const Trajectory far_plan = shifted(p.plan, d, d);
  const EpisodeMetrics here = runEpisode(p.scenario, p.plan, ExecutionDef{}).metrics;
  const EpisodeMetrics there = runEpisode(far, far_plan, ExecutionDef{}).metrics;
  std::printf("%s: steps %ld / %ld, rest %d / %d, max %.9g / %.9g, goal %.9g / %.9g\n", GetParam(),
              here.steps, there.steps, here.ended_at_rest, there.ended_at_rest, here.max_pos_err_m,
              there.max_pos_err_m, here.goal_pos_err_m, there.goal_pos_err_m);
  EXPECT_NEAR(there.max_pos_err_m, here.max_pos_err_m, 1e-6);
  EXPECT_NEAR(there.rms_pos_err_m, here.rms_pos_err_m, 1e-6);
  // Where the robot comes to rest after the plan (the closed loop holding the last pose below
  // 0.2 mm/s) turns the inputs' 1e-12 m rounding at 10 km into differences of up to ~1e-6 m
  // (measured 1.1e-6 m on parallel, 7e-9 m on head_in); the tracking itself stays within 1e-6.
  EXPECT_NEAR(there.final_pos_err_m, here.final_pos_err_m, 1e-5);
  EXPECT_NEAR(there.goal_pos_err_m, here.goal_pos_err_m, 1e-5);
  // The same ~1e-6 m at rest, as a difference between the wheels 85 mm apart: ~2e-5 rad, 1e-3
  // deg (measured 1.1e-4 deg on today's parallel plan).
  EXPECT_NEAR(there.goal_heading_err_deg, here.goal_heading_err_deg, 1e-3);
  EXPECT_EQ(there.contacts, here.contacts);
  // lab: its encoder counts and stiction turn the inputs' 1e-12 m rounding at 10 km into
  // different discrete events, which move its errors by some 10 um (as any 1-ulp change of an
  // input does); still the same robot, not a broken one.
  const EpisodeMetrics lab_here = runEpisode(p.scenario, p.plan, withRealism("lab", 1)).metrics;
  const EpisodeMetrics lab_there = runEpisode(far, far_plan, withRealism("lab", 1)).metrics;
  EXPECT_NEAR(lab_there.max_pos_err_m, lab_here.max_pos_err_m, 2e-4);
  EXPECT_NEAR(lab_there.goal_pos_err_m, lab_here.goal_pos_err_m, 2e-4);
  EXPECT_EQ(lab_there.contacts, 0);
}

TEST_P(RealismWorlds, A200MetreLotDrivesAsAccuratelyAsTheStudyLot) {
  const Planned& p = planned(GetParam());
  Scenario big = p.scenario;
  big.lot.x_max_m = 200.0;
  big.lot.y_max_m = 200.0;
  const EpisodeMetrics small = runEpisode(p.scenario, p.plan, ExecutionDef{}).metrics;
  const EpisodeMetrics large = runEpisode(big, p.plan, ExecutionDef{}).metrics;
  EXPECT_NEAR(large.max_pos_err_m, small.max_pos_err_m, 1e-6);
  EXPECT_NEAR(large.goal_pos_err_m, small.goal_pos_err_m, 1e-6);
  EXPECT_EQ(large.contacts, 0);
}

TEST_P(RealismWorlds, ParkedRobotsFarAwayChangeNothing) {
  const Planned& p = planned(GetParam());
  Scenario crowded = p.scenario;
  for (int i = 0; i < 400; ++i) {
    testing::addParkedRobot(crowded, "far_" + std::to_string(i),
                            {20.0 + 0.2 * (i % 20), 20.0 + 0.2 * (i / 20), 0.0});
  }
  const EpisodeMetrics a = runEpisode(p.scenario, p.plan, ExecutionDef{}).metrics;
  const EpisodeMetrics b = runEpisode(crowded, p.plan, ExecutionDef{}).metrics;
  // More proxies in the broadphase's tree may reorder the contact pairs it reports (float
  // rounding in the solver), nothing more.
  EXPECT_NEAR(b.max_pos_err_m, a.max_pos_err_m, 1e-6);
  EXPECT_NEAR(b.goal_pos_err_m, a.goal_pos_err_m, 1e-6);
  EXPECT_EQ(b.contacts, a.contacts);
  EXPECT_EQ(b.parked.size(), a.parked.size() + 400);
  EXPECT_EQ(b.max_parked_displacement_m, a.max_parked_displacement_m);
}

// In a world with more parked robots than SimModelDef::parked_lazy_count, they enter Bullet only
// when the robot comes near: one in the robot's path is still hit, named, and pushed.
TEST(LazyParkedRobots, ARobotInThePathIsStillHitAndPushedAmongMany) {
  Scenario s = testing::emptyLot({0.5, 0.5, 0.0});
  s.lot = {0.0, 0.0, 40.0, 40.0};
  for (int i = 0; i < 100; ++i) {
    testing::addParkedRobot(s, "far_" + std::to_string(i),
                            {10.0 + 0.3 * (i % 10), 10.0 + 0.3 * (i / 10), 0.0});
  }
  ASSERT_GT(s.obstacles.size(), SimModelDef{}.parked_lazy_count);
  // 0.6 m ahead: inserted only once the robot has driven ~0.25 m.
  testing::addParkedRobot(s, "robot_ahead", {0.5 + 0.6, 0.5, 0.0});
  const Trajectory plan = testing::planFromSegments(
      s.start, testing::rampedSegments({5.0, 5.0}, 6.5, s.robot), s.robot);
  const EpisodeMetrics m = runEpisode(s, plan).metrics;
  ASSERT_GE(m.contacts, 1);
  EXPECT_EQ(m.first_contact_body, "robot_ahead");
  // Pushed: how far is chaotic (docs/simulation.md), and marginal here: the robot's wheels carry
  // 0.14 kg (1.37 N of traction) against the 1.23 N that slides a 0.25 kg parked robot at
  // friction 0.5 (1.6 mm with the warm-started solver); untouched ones stay below 0.1 mm.
  EXPECT_GT(m.max_parked_displacement_m, 0.001);
  for (const ParkedRobotDisplacement& p : m.parked) {
    if (p.name != "robot_ahead") {
      EXPECT_EQ(p.max_m, 0.0) << p.name;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Sim, RealismWorlds, ::testing::Values("head_in", "parallel"));

}  // namespace
}  // namespace parksim
