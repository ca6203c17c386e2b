// Episode::step(command): an episode driven by wheel speeds from outside (a user's controller).

#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "parksim/core/io/Error.h"
#include "parksim/realism/RealismDef.h"
#include "parksim/results/episode/ExecutedFile.h"
#include "parksim/results/episode/JsonFile.h"
#include "parksim/results/episode/MetricsFile.h"
#include "parksim/sim/episode/Episode.h"
#include "tests/sim/SimTestSupport.h"

namespace parksim {
namespace {

Trajectory straightPlan(const Scenario& s) {
  return testing::planFromSegments(s.start, testing::rampedSegments({5.0, 5.0}, 1.0, s.robot),
                                   s.robot);
}

TEST(EpisodeCommand, CommandingTheControllersOwnCommandIsBitIdenticalToStep) {
  Scenario s = testing::emptyLot({0.5, 0.5, 0.3});
  const Trajectory plan = straightPlan(s);
  s.goal.pose = plan.points.back().pose;
  for (TrackingMode mode : {TrackingMode::kClosed, TrackingMode::kOpen}) {
    ExecutionDef def;
    def.tracking = mode;
    const EpisodeResult reference = runEpisode(s, plan, def);
    Episode episode(s, plan, def);
    while (!episode.finished()) episode.step(episode.controllerCommand());
    EXPECT_EQ(executedCsv(episode.rows()), executedCsv(reference.rows)) << toString(mode);
    EXPECT_EQ(episode.metrics().steps, reference.metrics.steps);
  }
}

// Physics no simulation can integrate ends in an error, not in NaN metrics. The world reader
// refuses such values since issue 22 (PhysicalRanges.h), so the guard is tested here, on a
// scenario built without the reader (it was HostileInputTest's gravity of 1e300).
TEST(EpisodeCommand, PhysicsThatDivergesIsAnErrorNotNanMetrics) {
  Scenario s = testing::emptyLot({0.5, 0.5, 0.3});
  const Trajectory plan = straightPlan(s);
  s.goal.pose = plan.points.back().pose;
  s.physics.gravity_mps2 = 1e300;
  try {
    (void)runEpisode(s, plan, ExecutionDef{});
    FAIL() << "a gravity of 1e300 m/s^2 ran";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()).rfind("simulation: diverged at t = ", 0), 0u) << e.what();
  }
}

TEST(EpisodeCommand, UnderARealismTheCommandGoesThroughItsControlLoop) {
  // The lab preset: motors, encoders, an estimator and a control loop with latency. Commanding
  // what the controller would command at every step is then still the controller.
  Scenario s = testing::emptyLot({0.5, 0.5, 0.3});
  const Trajectory plan = straightPlan(s);
  s.goal.pose = plan.points.back().pose;
  ExecutionDef def;
  def.realism = presetRealism("lab");
  def.noise_seed = 3;
  const EpisodeResult reference = runEpisode(s, plan, def);
  Episode episode(s, plan, def);
  while (!episode.finished()) episode.step(episode.controllerCommand());
  EXPECT_EQ(executedCsv(episode.rows()), executedCsv(reference.rows));
}

TEST(EpisodeCommand, TheCommandIsAppliedAndRecordedAndTheRobotFollowsIt) {
  const Scenario s = testing::emptyLot({0.5, 0.5, 0.0});
  const Trajectory plan = straightPlan(s);
  Episode episode(s, plan);
  const WheelSpeeds forward{4.0, 4.0};
  // 1 s at 4 rad/s on 20 mm wheels: 80 mm once the motors are at speed (they accelerate within
  // a few steps), straight ahead.
  const long steps = std::lround(1.0 / episode.world().timeStep());
  for (long k = 0; k < steps; ++k) episode.step(forward);
  const ExecutedRow& last = episode.rows().back();
  EXPECT_EQ(last.wheels_cmd, forward);
  EXPECT_NEAR(last.wheels.left_radps, 4.0, 0.05);
  EXPECT_NEAR(last.pose.x - s.start.x, 4.0 * s.robot.wheel_radius_m * 1.0, 0.003);
  EXPECT_NEAR(last.pose.y, s.start.y, 0.001);
  EXPECT_FALSE(episode.finished());
}

TEST(EpisodeCommand, StandingStillEndsAtRestAfterThePlansEnd) {
  Scenario s = testing::emptyLot({0.5, 0.5, 0.0});
  const Trajectory plan = straightPlan(s);
  Episode episode(s, plan);
  long steps = 0;
  while (!episode.finished() && steps < 100000) {
    episode.step(WheelSpeeds{});
    ++steps;
  }
  const EpisodeMetrics m = episode.metrics();
  EXPECT_TRUE(m.ended_at_rest);
  // The robot never left the start, so the tracking error at the end is the plan's length.
  EXPECT_NEAR(m.final_pos_err_m, positionDistance(plan.points.back().pose, s.start), 1e-3);
  EXPECT_GE(m.sim_time_s, plan.duration());
}

}  // namespace
}  // namespace parksim
