// The simulation's accuracy on fixed plans, so that changes to the physics step (speed work,
// issue 21) are held to what it measured before them, and a new default planner does not move
// the check: the plans are files (tests/sim/fixtures/), made at c28d3c6 with
//   parksim plan worlds/head_in.yaml --seed 1        (the defaults then: hybrid-a-star,
//   parksim plan worlds/parallel.yaml --seed 1        reeds-shepp, time-optimal timing)
//   parksim plan worlds/head_in.yaml --planner rrt-goal-connect --steering move-to-pose
//       --timing study --seed 1                      (the study's plan, 331 rows, 33 s)
// and the recorded values are what parksim measured on them at c28d3c6 (docs/simulation.md).

#include <cstdio>
#include <ostream>
#include <string>

#include <gtest/gtest.h>

#include "parksim/results/episode/TrajectoryFile.h"
#include "parksim/scenario/world/ScenarioReader.h"
#include "parksim/sim/episode/Episode.h"
#include "tests/support/TestPaths.h"

namespace parksim {
namespace {

// Closed-loop metrics may move by at most this from their recorded values, m.
constexpr double kClosedLoopTolerance_m = 0.05e-3;

struct Recorded {
  friend void PrintTo(const Recorded& r, std::ostream* os) { *os << r.world; }
  const char* world;
  const char* plan;
  double max_pos_err_m;
  double rms_pos_err_m;
  double final_pos_err_m;
  double goal_pos_err_m;
};

EpisodeMetrics drive(const std::string& world, const std::string& plan, TrackingMode tracking) {
  const std::string root = parksim::testing::sourceDir();
  const Scenario s = loadScenario(root + "/worlds/" + world + ".yaml");
  const Trajectory p = readTrajectoryCsv(root + "/tests/sim/fixtures/" + plan);
  ExecutionDef def;
  def.tracking = tracking;
  const EpisodeMetrics m = runEpisode(s, p, def).metrics;
  std::printf(
      "%s %s: max %.6f mm rms %.6f mm final %.6f mm / %.6f deg goal %.6f mm / %.6f deg, "
      "contacts %d, %ld steps\n",
      world.c_str(), toString(tracking), m.max_pos_err_m * 1e3, m.rms_pos_err_m * 1e3,
      m.final_pos_err_m * 1e3, m.final_heading_err_deg, m.goal_pos_err_m * 1e3,
      m.goal_heading_err_deg, m.contacts, m.steps);
  return m;
}

class RecordedPlans : public ::testing::TestWithParam<Recorded> {};

TEST_P(RecordedPlans, ClosedLoopMetricsStayWithinFiftyMicrometresOfTheRecord) {
  const Recorded& r = GetParam();
  const EpisodeMetrics m = drive(r.world, r.plan, TrackingMode::kClosed);
  EXPECT_NEAR(m.max_pos_err_m, r.max_pos_err_m, kClosedLoopTolerance_m);
  EXPECT_NEAR(m.rms_pos_err_m, r.rms_pos_err_m, kClosedLoopTolerance_m);
  EXPECT_NEAR(m.final_pos_err_m, r.final_pos_err_m, kClosedLoopTolerance_m);
  EXPECT_NEAR(m.goal_pos_err_m, r.goal_pos_err_m, kClosedLoopTolerance_m);
  EXPECT_EQ(m.contacts, 0);
  EXPECT_EQ(m.max_parked_displacement_m, 0.0);  // untouched: not moved by a bit
  EXPECT_TRUE(m.goal_reached);
  EXPECT_TRUE(m.ended_at_rest);
}

// Recorded at c28d3c6 (Release, Bullet 3.24 float).
INSTANTIATE_TEST_SUITE_P(Sim, RecordedPlans,
                         ::testing::Values(Recorded{"head_in", "head_in_seed1_trajectory.csv",
                                                    0.6192026723435625e-3, 0.16033500419625074e-3,
                                                    0.06176548253010131e-3, 0.06176548253186864e-3},
                                           Recorded{"parallel", "parallel_seed1_trajectory.csv",
                                                    0.6586676885994744e-3, 0.08820900459159236e-3,
                                                    0.08949325517401402e-3, 0.0894932551751143e-3}),
                         [](const ::testing::TestParamInfo<Recorded>& param) {
                           return std::string(param.param.world);
                         });

// Issue 21's accuracy bound: the study's plan driven open loop ends within 6 mm of where the
// plan ends (5.917 mm at c28d3c6; MuJoCo's tuned model: 16.6 mm). Not a convergence measure:
// the slip at the plan's wheel-speed steps grows as the solver converges there (200-400
// iterations a step: 6.3 mm). A build without the transcription of Bullet's solver runs
// Bullet's own with 100 cold iterations (SimModelDef::cold_solver_iterations), closer to that:
// 6.07 mm measured, held to 6.5 mm.
TEST(RecordedPlans, TheStudyPlanOpenLoopEndsWithinSixMillimetres) {
  const EpisodeMetrics m = drive("head_in", "head_in_study_trajectory.csv", TrackingMode::kOpen);
  const bool transcription = effectiveSolverKernel(SolverKernel::kFast) == SolverKernel::kFast;
  const double bound_m = transcription ? 0.006 : 0.0065;
  EXPECT_LE(m.final_pos_err_m, bound_m);
  EXPECT_LE(m.max_pos_err_m, bound_m);
  EXPECT_EQ(m.contacts, 0);
}

}  // namespace
}  // namespace parksim
