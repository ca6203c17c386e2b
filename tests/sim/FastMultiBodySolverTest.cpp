// parksim's solver kernels against Bullet's own btMultiBodyConstraintSolver: without warm
// starting, kExact must give the same bytes, kFast the same motion up to float rounding; warm
// starting converges steady driving that cold-started iterations leave unconverged.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include <gtest/gtest.h>

#include "parksim/results/ExecutedFile.h"
#include "parksim/results/JsonFile.h"
#include "parksim/results/MetricsFile.h"
#include "parksim/sim/episode/Episode.h"
#include "parksim/sim/world/DynamicsWorld.h"
#include "tests/sim/SimTestSupport.h"

namespace parksim {
namespace {

using testing::Segment;

// Forward arc, turn in place, reverse arc, then straight through a parked robot into a wall:
// wheel contacts, the slider, motors at their torque limit, a woken parked robot pushed over
// the ground (rigid-body rows) and the chassis against a fixed box.
struct Case {
  Scenario scenario;
  Trajectory plan;
};

Case pushCase(bool with_obstacles = true) {
  Case c;
  c.scenario = testing::emptyLot({0.5, 0.5, 0.0});
  std::vector<Segment> segs;
  auto add = [&](const std::vector<Segment>& more) {
    segs.insert(segs.end(), more.begin(), more.end());
  };
  add(testing::rampedSegments({6.0, 8.0}, 1.0, c.scenario.robot));
  add(testing::rampedSegments({-4.0, 4.0}, 0.5, c.scenario.robot));
  add(testing::rampedSegments({-7.0, -5.0}, 0.8, c.scenario.robot));
  add(testing::rampedSegments({5.0, 5.0}, 2.0, c.scenario.robot));
  c.plan = testing::planFromSegments(c.scenario.start, segs, c.scenario.robot);
  if (!with_obstacles) return c;
  // Ahead of where the straight part starts, so the robot pushes it and then meets the wall.
  const Pose2 end = c.plan.points.back().pose;
  const double cx = std::cos(end.theta), sy = std::sin(end.theta);
  testing::addParkedRobot(c.scenario, "robot_ahead",
                          {end.x - 0.12 * cx, end.y - 0.12 * sy, end.theta});
  testing::addWall(c.scenario, "wall", end.x + 0.08 * cx - 0.05, end.y + 0.08 * sy - 0.05,
                   end.x + 0.08 * cx + 0.05, end.y + 0.08 * sy + 0.05);
  return c;
}

EpisodeResult run(const Case& c, TrackingMode mode, SolverKernel kernel,
                  double residual_threshold = SimModelDef{}.solver_residual_threshold) {
  ExecutionDef def;
  def.tracking = mode;
  SimModelDef model;
  model.solver = kernel;
  model.solver_residual_threshold = residual_threshold;
  model.warm_start = false;
  Episode episode(c.scenario, c.plan, def, model);
  while (!episode.finished()) episode.step();
  return {episode.metrics(), episode.rows(), {}};
}

// With the default early exit too: the residuals are bit-identical, so both stop at the same
// iteration.
TEST(FastMultiBodySolver, ExactKernelIsBitIdenticalToBullets) {
  const Case c = pushCase();
  for (TrackingMode mode : {TrackingMode::kClosed, TrackingMode::kOpen}) {
    const EpisodeResult bullet = run(c, mode, SolverKernel::kBullet);
    const EpisodeResult exact = run(c, mode, SolverKernel::kExact);
    // The case exercises what it is meant to.
    EXPECT_GE(bullet.metrics.contacts, 1) << toString(mode);
    EXPECT_GT(bullet.metrics.max_parked_displacement_m, 0.001) << toString(mode);
    EXPECT_TRUE(executedCsv(bullet.rows) == executedCsv(exact.rows)) << toString(mode);
    EXPECT_EQ(bullet.metrics.contacts, exact.metrics.contacts);
    EXPECT_EQ(bullet.metrics.max_parked_displacement_m, exact.metrics.max_parked_displacement_m);
  }
}

// Every iteration is run (no early exit: where the residual crosses a threshold depends on
// the rounding too). kFast also sets the robot's rows up from its constant inverse mass
// (MultiBodyInverseMass.h) and finds the wheels' ground contacts as the exact closest point
// (SphereBoxContacts.h) where Bullet runs GJK to its tolerance: driving on free ground the
// difference stays within a few micrometres (1.4 um measured). Pushing a box is chaotic (which
// way it turns depends on the last bits), so there only the events must agree.
TEST(FastMultiBodySolver, FastKernelDiffersFromBulletsByMicrometresOnly) {
  for (bool with_obstacles : {false, true}) {
    const Case c = pushCase(with_obstacles);
    for (TrackingMode mode : {TrackingMode::kClosed, TrackingMode::kOpen}) {
      const EpisodeResult bullet = run(c, mode, SolverKernel::kBullet, 0.0);
      const EpisodeResult fast = run(c, mode, SolverKernel::kFast, 0.0);
      const std::size_t n = std::min(bullet.rows.size(), fast.rows.size());
      double max_diff = 0.0;
      for (std::size_t k = 0; k < n; ++k) {
        max_diff = std::max(max_diff, positionDistance(bullet.rows[k].pose, fast.rows[k].pose));
      }
      std::printf(
          "%s, %s: kFast vs kBullet: max pose difference %.3g mm over %zu rows, "
          "parked %.4f / %.4f mm, contacts %d / %d\n",
          with_obstacles ? "pushing" : "free", toString(mode), max_diff * 1e3, n,
          bullet.metrics.max_parked_displacement_m * 1e3,
          fast.metrics.max_parked_displacement_m * 1e3, bullet.metrics.contacts,
          fast.metrics.contacts);
      if (!with_obstacles) {
        EXPECT_LT(max_diff, 5e-6) << toString(mode);
        EXPECT_EQ(bullet.rows.size(), fast.rows.size());
      }
      EXPECT_EQ(bullet.metrics.first_contact_body, fast.metrics.first_contact_body);
      EXPECT_NEAR(bullet.metrics.first_contact_t_s, fast.metrics.first_contact_t_s, 0.01);
      // While the robot pushes, contact points flicker; whether a gap outlasts the merge window
      // (ExecutionDef::contact_merge_s) once more is in the last bits, so the event counts may
      // differ by one (5 against 4 with the tracking gains of issue 30).
      EXPECT_NEAR(bullet.metrics.contacts, fast.metrics.contacts, 1) << toString(mode);
    }
  }
}

// Warm starting (SolverWarmStart.h) against the converged answer: wheel speeds held from rest
// for 5 s, the default model (15 iterations at most, warm-started) ends within 0.04 mm (straight)
// and 0.09 mm (arc; most of it from the start, where the warm start has nothing to start from)
// of where 300 cold iterations per step end; 15 cold iterations end 0.46 and 1.38 mm away.
TEST(FastMultiBodySolver, WarmStartedStepsEndWhereConvergedStepsEnd) {
  const Scenario base = testing::emptyLot({0.5, 0.5, 0.3});
  auto drive = [&](const WheelSpeeds& wheels, int iterations, bool warm, double threshold) {
    Scenario s = base;
    s.physics.solver_iterations = iterations;
    SimModelDef model;
    model.warm_start = warm;
    model.solver_residual_threshold = threshold;
    DynamicsWorld world(s, s.start, model);
    world.setWheelTargets(wheels);
    for (int k = 0; k < 1200; ++k) world.step();
    return world.robot().pose;
  };
  for (const WheelSpeeds& wheels : {WheelSpeeds{5.0, 5.0}, WheelSpeeds{3.0, 6.0}}) {
    const Pose2 converged = drive(wheels, 300, false, 0.0);
    const Pose2 warm = drive(wheels, PhysicsDef{}.solver_iterations, true,
                             SimModelDef{}.solver_residual_threshold);
    const Pose2 cold = drive(wheels, PhysicsDef{}.solver_iterations, false,
                             SimModelDef{}.solver_residual_threshold);
    const double warm_err = positionDistance(warm, converged);
    const double cold_err = positionDistance(cold, converged);
    std::printf("wheels %.0f/%.0f: from the converged pose, warm %.4f mm, cold %.4f mm\n",
                wheels.left_radps, wheels.right_radps, warm_err * 1e3, cold_err * 1e3);
    EXPECT_LT(warm_err, 0.15e-3);
    EXPECT_GT(cold_err, 4.0 * warm_err);
  }
}

}  // namespace
}  // namespace parksim
