// The two solver paths on the same episodes: parksim's transcription of Bullet 3.24's solver
// (parksim/sim/bullet/README.md; the kExact and kFast kernels) and Bullet's own
// btMultiBodyConstraintSolver (kBullet). A build without the transcription (another Bullet, or
// PARKSIM_BULLET_FAST_SOLVER off) runs Bullet's own for every kernel (world/KernelParts.h): there
// both sides of each comparison are Bullet's own, and must be the same bytes.

#include <LinearMath/btScalar.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "parksim/results/episode/ExecutedFile.h"
#include "parksim/results/episode/TrajectoryFile.h"
#include "parksim/scenario/world/ScenarioReader.h"
#include "parksim/sim/episode/Episode.h"
#include "parksim/sim/world/DynamicsWorld.h"
#include "tests/sim/SimTestSupport.h"
#include "tests/support/TestPaths.h"

namespace parksim {
namespace {

using testing::Segment;

bool transcriptionBuilt() {
  return effectiveSolverKernel(SolverKernel::kFast) != SolverKernel::kBullet;
}

struct Case {
  std::string name;
  Scenario scenario;
  Trajectory plan;
};

// Forward arc, turn in place, reverse arc, then straight through a parked robot into a wall:
// wheel contacts, the slider, motors at their torque limit, a woken parked robot pushed over
// the ground (rigid-body rows) and the chassis against a fixed box.
Case pushCase(bool with_obstacles) {
  Case c;
  c.name = with_obstacles ? "pushing" : "free";
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

// A study world with a plan recorded in tests/sim/fixtures/ (RecordedPlansTest.cpp says how).
Case recordedCase(const std::string& world, const std::string& plan) {
  const std::string root = parksim::testing::sourceDir();
  Case c;
  c.name = plan;
  c.scenario = loadScenario(root + "/worlds/" + world + ".yaml");
  c.plan = readTrajectoryCsv(root + "/tests/sim/fixtures/" + plan);
  return c;
}

EpisodeResult run(const Case& c, TrackingMode mode, const SimModelDef& model) {
  ExecutionDef def;
  def.tracking = mode;
  Episode episode(c.scenario, c.plan, def, model);
  while (!episode.finished()) episode.step();
  return {episode.metrics(), episode.rows(), {}};
}

SimModelDef coldModel(SolverKernel kernel, double residual_threshold) {
  SimModelDef model;
  model.solver = kernel;
  model.warm_start = false;
  model.solver_residual_threshold = residual_threshold;
  return model;
}

double maxPoseDifference(const EpisodeResult& a, const EpisodeResult& b) {
  const std::size_t n = std::min(a.rows.size(), b.rows.size());
  double max_diff = 0.0;
  for (std::size_t k = 0; k < n; ++k) {
    max_diff = std::max(max_diff, positionDistance(a.rows[k].pose, b.rows[k].pose));
  }
  return max_diff;
}

TEST(SolverPaths, OnlyABuildAgainstBullet324RunsTheTranscription) {
  const bool built = transcriptionBuilt();
  if (built) EXPECT_EQ(BT_BULLET_VERSION, 324);
  for (SolverKernel k : {SolverKernel::kBullet, SolverKernel::kExact, SolverKernel::kFast}) {
    EXPECT_EQ(effectiveSolverKernel(k), built ? k : SolverKernel::kBullet);
  }
}

// Without warm starting (Bullet's own solver has none for multibodies) kExact performs Bullet's
// float operations in Bullet's order: the difference must be 0, the same bytes, with the early
// exit too (the residuals are bit-identical, so both stop at the same iteration).
TEST(SolverPaths, TheExactTranscriptionIsBitIdenticalToBulletsOwn) {
  const Case c = pushCase(true);
  const double threshold = SimModelDef{}.solver_residual_threshold;
  for (TrackingMode mode : {TrackingMode::kClosed, TrackingMode::kOpen}) {
    const EpisodeResult bullet = run(c, mode, coldModel(SolverKernel::kBullet, threshold));
    const EpisodeResult exact = run(c, mode, coldModel(SolverKernel::kExact, threshold));
    // The case exercises what it is meant to.
    EXPECT_GE(bullet.metrics.contacts, 1) << toString(mode);
    EXPECT_GT(bullet.metrics.max_parked_displacement_m, 0.001) << toString(mode);
    EXPECT_TRUE(executedCsv(bullet.rows) == executedCsv(exact.rows)) << toString(mode);
    EXPECT_EQ(bullet.metrics.contacts, exact.metrics.contacts);
    EXPECT_EQ(bullet.metrics.max_parked_displacement_m, exact.metrics.max_parked_displacement_m);
  }
}

// kFast sums each row's 8-term dot products as two 4-lane halves (reassociation), sets the
// robot's rows up from its constant inverse mass (Bullet's articulated-body pass to float
// rounding, MultiBodyInverseMassTest) and finds the wheels' ground contacts as the exact closest
// point where Bullet's GJK stops within its tolerance. Every iteration is run (where an early
// exit stops depends on the rounding too). On free ground that is rounding only: 1.4 um over the
// manoeuvre measured, bounded at 5 um. Pushing a box is chaotic (which way it turns depends on
// the last bits), so there only the events must agree.
TEST(SolverPaths, TheFastTranscriptionDiffersFromBulletsOwnByRoundingOnly) {
  for (bool with_obstacles : {false, true}) {
    const Case c = pushCase(with_obstacles);
    for (TrackingMode mode : {TrackingMode::kClosed, TrackingMode::kOpen}) {
      const EpisodeResult bullet = run(c, mode, coldModel(SolverKernel::kBullet, 0.0));
      const EpisodeResult fast = run(c, mode, coldModel(SolverKernel::kFast, 0.0));
      const double max_diff = maxPoseDifference(bullet, fast);
      std::printf(
          "%s, %s: kFast vs kBullet: max pose difference %.3g mm over %zu rows, "
          "parked %.4f / %.4f mm, contacts %d / %d\n",
          c.name.c_str(), toString(mode), max_diff * 1e3, fast.rows.size(),
          bullet.metrics.max_parked_displacement_m * 1e3,
          fast.metrics.max_parked_displacement_m * 1e3, bullet.metrics.contacts,
          fast.metrics.contacts);
      if (!transcriptionBuilt()) {
        EXPECT_TRUE(executedCsv(bullet.rows) == executedCsv(fast.rows)) << c.name;
      }
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

// The default (kFast, warm started, at most PhysicsDef's 15 iterations) against what a build
// without the transcription runs in its place: Bullet's own solver, every row from zero, at
// least SimModelDef::cold_solver_iterations a step. Not rounding: the same model solved to a
// different convergence where it is hardest, at the plans' wheel-speed steps and at rest.
// Closed loop the controller takes out what either leaves, so the robots stay within
// kClosedBound_m of each other; open loop the slip at the steps stays in the pose (kOpenBound_m).
// Bounds: the largest difference measured on these plans, times about 1.5 (docs/simulation.md,
// "Bullet's internals fenced").
TEST(SolverPaths, BulletsOwnPathDrivesTheRecordedPlansAsTheDefaultDoes) {
  constexpr double kClosedBound_m = 0.15e-3;
  constexpr double kOpenBound_m = 2.5e-3;
  struct Drive {
    Case c;
    TrackingMode mode;
  };
  const Drive drives[] = {
      {recordedCase("head_in", "head_in_seed1_trajectory.csv"), TrackingMode::kClosed},
      {recordedCase("parallel", "parallel_seed1_trajectory.csv"), TrackingMode::kClosed},
      {recordedCase("head_in", "head_in_study_trajectory.csv"), TrackingMode::kClosed},
      {recordedCase("head_in", "head_in_study_trajectory.csv"), TrackingMode::kOpen},
      {recordedCase("head_in", "head_in_seed1_trajectory.csv"), TrackingMode::kOpen}};
  for (const Drive& d : drives) {
    const SimModelDef model;  // the default: kFast where the build has it
    const EpisodeResult fast = run(d.c, d.mode, model);
    Case own_case = d.c;
    own_case.scenario.physics.solver_iterations =
        std::max(d.c.scenario.physics.solver_iterations, model.cold_solver_iterations);
    SimModelDef own_model = model;
    own_model.solver = SolverKernel::kBullet;
    const EpisodeResult own = run(own_case, d.mode, own_model);
    const double max_diff = maxPoseDifference(fast, own);
    const EpisodeMetrics& a = fast.metrics;
    const EpisodeMetrics& b = own.metrics;
    std::printf(
        "%s, %s: default vs Bullet's own: max pose difference %.4f mm; final error %.4f / "
        "%.4f mm, max %.4f / %.4f mm\n",
        d.c.name.c_str(), toString(d.mode), max_diff * 1e3, a.final_pos_err_m * 1e3,
        b.final_pos_err_m * 1e3, a.max_pos_err_m * 1e3, b.max_pos_err_m * 1e3);
    if (!transcriptionBuilt()) {
      EXPECT_TRUE(executedCsv(fast.rows) == executedCsv(own.rows)) << d.c.name;
    }
    const bool closed = d.mode == TrackingMode::kClosed;
    EXPECT_LE(max_diff, closed ? kClosedBound_m : kOpenBound_m) << d.c.name << toString(d.mode);
    EXPECT_EQ(a.contacts, b.contacts) << d.c.name;
    EXPECT_EQ(a.goal_reached, b.goal_reached) << d.c.name;
  }
}

}  // namespace
}  // namespace parksim
