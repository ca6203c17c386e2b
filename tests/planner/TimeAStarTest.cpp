#include "parksim/planner/search/TimeAStar.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "parksim/core/io/Error.h"
#include "parksim/planner/base/PlanScenario.h"
#include "tests/support/PlanChecks.h"
#include "tests/support/StudyLot.h"

namespace parksim {
namespace {

using testing::expectValidPlan;
using testing::SatChecker;

TEST(TimeAStar, PlansTheStudyLotInTime) {
  for (bool parallel : {false, true}) {
    SCOPED_TRACE(parallel ? "parallel" : "head-in");
    const Scenario s = parallel ? testing::studyLotParallel() : testing::studyLot();
    const SatChecker checker(s);
    const PlanSetup setup;  // the defaults: time-a-star, smoothed
    const PlanResult r = planScenario(s, checker, setup);
    expectValidPlan(s, checker, setup, r);
    EXPECT_EQ(r.objective, PlanObjective::kDuration);
    EXPECT_EQ(r.cost, r.trajectory.duration());
    EXPECT_GE(r.trajectory.duration(), r.free_space_bound_s);
    EXPECT_LE(r.trajectory.duration(), 1.3 * r.free_space_bound_s);
    // Rows every 0.02 s, the soft start's first step a jerk step above rest.
    EXPECT_NEAR(r.trajectory.points[1].t_s, setup.timing_period_s, 1e-12);
    const WheelSpeeds& first = r.trajectory.points.front().wheels;
    EXPECT_LE(std::max(std::abs(first.left_radps), std::abs(first.right_radps)),
              setup.start_jerk_radps3 * setup.timing_period_s * setup.timing_period_s + 1e-9);
  }
}

// The tree planners steer between samples anywhere in the lot, so a 10 km lot is refused for
// them before planning; the A* planners' trajectories follow the problem, so the same metres-long
// problem is accepted for them, and a start 7 km from its goal is refused by that distance.
TEST(TimeAStar, ItsLimitsFollowTheProblemNotTheLot) {
  Scenario s = testing::studyLot();
  s.lot = {0.0, 0.0, 10000.0, 10000.0};
  PlanSetup setup;
  EXPECT_NO_THROW(checkPlanningLimits(s, setup));
  setup.planner = "hybrid-a-star";
  EXPECT_NO_THROW(checkPlanningLimits(s, setup));
  setup.planner = "rrt-connect";
  EXPECT_THAT([&] { checkPlanningLimits(s, setup); },
              ::testing::ThrowsMessage<Error>(::testing::HasSubstr("across the lot")));
  setup = PlanSetup{};
  s.goal.pose = {7000.0, 0.04, -kPi / 2};
  EXPECT_THAT([&] { checkPlanningLimits(s, setup); },
              ::testing::ThrowsMessage<Error>(::testing::HasSubstr("from the start to the goal")));
}

// A start that already is the goal pose: the path is empty, and that is a solution (it was
// refused as "no trajectory within 200000 expansions" while an empty path meant "none found"),
// as every other planner returns it.
TEST(TimeAStar, AStartAtTheGoalIsSolvedWithoutMoving) {
  Scenario s = testing::studyLot();
  s.start = s.goal.pose;
  const SatChecker checker(s);
  for (const std::string& kind : builtInPlanners().names()) {
    SCOPED_TRACE(kind);
    PlanSetup setup;
    setup.planner = kind;
    const PlanResult r = planScenario(s, checker, setup);
    ASSERT_TRUE(r.solved()) << r.message;
    EXPECT_EQ(r.trajectory.duration(), 0.0);
    EXPECT_EQ(r.trajectory.points.back().pose, s.goal.pose);
  }
}

// The same problem in a 200 m and in a 1000 m lot: the same search, the same plan.
TEST(TimeAStar, TheProblemNotTheLotSetsTheSearch) {
  PlanResult results[2];
  int k = 0;
  for (double side : {200.0, 1000.0}) {
    Scenario s;
    s.lot = {0.0, 0.0, side, side};
    const double c = 0.5 * side;
    s.obstacles.push_back(Obstacle::makeBox(
        "wall", ObstacleKind::kWall, testing::cornerBox(c + 0.475, c - 0.6, 0.05, 1.2), 0.1));
    s.start = {c, c, 0.0};
    s.goal.pose = {c + 3.0, c + 0.3, kPi / 2};
    const SatChecker checker(s);
    PlanSetup setup;
    setup.search.max_iterations = 20000;  // a lot of 1 km^2 gets no more search than 200 m^2
    results[k] = planScenario(s, checker, setup);
    expectValidPlan(s, checker, setup, results[k]);
    ++k;
  }
  EXPECT_EQ(results[0].stats.iterations, results[1].stats.iterations);
  EXPECT_EQ(results[0].stats.tree_size, results[1].stats.tree_size);
  EXPECT_NEAR(results[0].trajectory.duration(), results[1].trajectory.duration(), 1e-9);
}

TEST(TimeAStar, WidensItsWindowWhenTheWayRoundIsLonger) {
  // Start and goal 0.4 m apart with a 3 m fence between: the first window (0.5 m around them)
  // holds no way round.
  Scenario s;
  s.lot = {0.0, 0.0, 4.0, 4.0};
  s.obstacles.push_back(Obstacle::makeBox("fence", ObstacleKind::kWall,
                                          testing::cornerBox(1.99, 0.5, 0.02, 3.5), 0.1));
  s.start = {1.8, 2.0, 0.0};
  s.goal.pose = {2.2, 2.0, 0.0};
  const SatChecker checker(s);
  const PlanSetup setup;
  const PlanResult r = planScenario(s, checker, setup);
  expectValidPlan(s, checker, setup, r);
  EXPECT_GT(r.trajectory.pathLength(s.robot), 3.0);
}

TEST(TimeAStar, AnytimeKeepsImprovingAndRecordsIt) {
  const Scenario s = testing::studyLot();
  const SatChecker checker(s);
  PlanSetup setup;
  setup.search.max_time_s = 0.3;
  const PlanResult anytime = planScenario(s, checker, setup);
  expectValidPlan(s, checker, setup, anytime);
  const std::vector<CostSample>& h = anytime.cost_history;
  for (std::size_t i = 1; i < h.size(); ++i) {
    EXPECT_LT(h[i].cost, h[i - 1].cost);
    EXPECT_GE(h[i].time_s, h[i - 1].time_s);
  }
  // Never worse than the one search without a time limit.
  const PlanResult once = planScenario(s, checker, PlanSetup{});
  EXPECT_LE(anytime.cost, once.cost + 1e-9);
}

TEST(TimeAStar, SameSeedSameBytesAndTheSearchIgnoresTheSeed) {
  const Scenario s = testing::studyLot();
  const SatChecker checker(s);
  PlanSetup setup;
  const PlanResult a = planScenario(s, checker, setup);
  const PlanResult b = planScenario(s, checker, setup);
  EXPECT_EQ(a.trajectory, b.trajectory);
  setup.search.seed = 99;  // draws other random shortcuts; the search is the same
  const PlanResult c = planScenario(s, checker, setup);
  EXPECT_EQ(a.stats.iterations, c.stats.iterations);
  setup.search.smooth = false;
  const PlanResult d = planScenario(s, checker, setup);
  setup.search.seed = 1;
  EXPECT_EQ(d.trajectory, planScenario(s, checker, setup).trajectory);
}

TEST(TimeAStar, RejectsBadDefinitions) {
  const Scenario s = testing::studyLot();
  const SatChecker checker(s);
  PlanSetup setup;
  setup.planner_params["heuristic_weight"] = "0.5";
  EXPECT_THROW(planScenario(s, checker, setup), Error);
  setup = {};
  setup.planner_params["arc_radii_m"] = "0.1,-0.1";
  EXPECT_THROW(planScenario(s, checker, setup), Error);
  setup = {};
  setup.timing_period_s = 0.0;
  EXPECT_THROW(planScenario(s, checker, setup), Error);
}

}  // namespace
}  // namespace parksim
