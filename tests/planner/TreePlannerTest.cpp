#include "planner/TreePlanner.h"

#include <gtest/gtest.h>

#include "planner/PlanScenario.h"
#include "tests/support/StudyLot.h"

namespace parksim {
namespace {

using testing::SatChecker;

// Independent check of a plan: consecutive poses follow from the wheel speeds, and the exact
// footprint (no margin) is free at poses 0.2 mm of travel apart (checked by SAT, not Bullet).
void expectFeasible(const Scenario& s, const Trajectory& t) {
  const SatChecker exact(s);
  for (std::size_t i = 0; i + 1 < t.points.size(); ++i) {
    const TrajectoryPoint& p = t.points[i];
    const double dt = t.points[i + 1].t_s - p.t_s;
    const Twist tw = toTwist(p.wheels, s.robot);
    const Pose2 next = integrateExact(p.pose, tw, dt);
    ASSERT_NEAR(next.x, t.points[i + 1].pose.x, 1e-4);
    ASSERT_NEAR(next.y, t.points[i + 1].pose.y, 1e-4);
    const double travel = (std::abs(tw.v_mps) + std::abs(tw.omega_radps) * 0.09) * dt;
    const int n = std::max(1, static_cast<int>(std::ceil(travel / 0.0002)));
    for (int k = 0; k < n; ++k) {
      ASSERT_TRUE(exact.isFree(integrateExact(p.pose, tw, dt * k / n))) << "t=" << p.t_s;
    }
  }
  const Pose2& end = t.points.back().pose;
  EXPECT_LE(positionDistance(end, s.goal.pose), s.goal.position_tolerance_m);
  EXPECT_LE(headingDistance(end, s.goal.pose), s.goal.heading_tolerance_rad);
  EXPECT_EQ(t.points.front().pose, s.start);
}

struct Case {
  PlannerKind kind;
  bool parallel;
};

class TreePlannerOnStudyLot : public ::testing::TestWithParam<Case> {};

TEST_P(TreePlannerOnStudyLot, SolvesOverSeedsWithFeasiblePaths) {
  const Scenario s = GetParam().parallel ? testing::studyLotParallel() : testing::studyLot();
  const SatChecker checker(s);
  PlanSetup setup;
  setup.planner.kind = GetParam().kind;
  int solved = 0;
  const int seeds = 20;
  for (int seed = 1; seed <= seeds; ++seed) {
    setup.planner.seed = seed;
    const PlanResult r = planScenario(s, checker, setup);
    if (!r.solved()) continue;
    ++solved;
    expectFeasible(s, r.trajectory);
    EXPECT_EQ(r.stats.tree_size, static_cast<int>(r.tree_edges.size()) + 1);
    EXPECT_GT(r.stats.collision_queries, 0);
  }
  // Goal-connect RRT must solve essentially always; basic RRT within 2000 iterations most times.
  EXPECT_GE(solved, GetParam().kind == PlannerKind::kRrtGoalConnect ? seeds : seeds * 3 / 4);
}

INSTANTIATE_TEST_SUITE_P(Study, TreePlannerOnStudyLot,
                         ::testing::Values(Case{PlannerKind::kRrtGoalConnect, false},
                                           Case{PlannerKind::kRrtGoalConnect, true},
                                           Case{PlannerKind::kRrt, false},
                                           Case{PlannerKind::kRrt, true}));

TEST(TreePlanner, SameSeedSameTrajectoryOtherSeedOtherTrajectory) {
  const Scenario s = testing::studyLotParallel();
  const SatChecker checker(s);
  PlanSetup setup;
  setup.planner.seed = 11;
  const PlanResult a = planScenario(s, checker, setup);
  const PlanResult b = planScenario(s, checker, setup);
  ASSERT_TRUE(a.solved());
  EXPECT_EQ(a.trajectory, b.trajectory);
  setup.planner.seed = 12;
  const PlanResult c = planScenario(s, checker, setup);
  ASSERT_TRUE(c.solved());
  EXPECT_NE(a.trajectory, c.trajectory);
}

TEST(TreePlanner, ReportsUnsolvedWithinIterationBudget) {
  Scenario s = testing::studyLot();
  // Wall off the parking row completely.
  Obstacle fence;
  fence.name = "fence";
  fence.box.center = {1.2, 0.25};
  fence.box.half_extents = {0.6, 0.01};
  s.obstacles.push_back(fence);
  const SatChecker checker(s);
  PlanSetup setup;
  setup.planner.max_iterations = 300;
  const PlanResult r = planScenario(s, checker, setup);
  EXPECT_EQ(r.status, PlanStatus::kIterationLimit);
  EXPECT_TRUE(r.trajectory.empty());
  EXPECT_EQ(r.stats.iterations, 300);
}

TEST(TreePlanner, InvalidStartAndGoalAreStatuses) {
  Scenario s = testing::studyLot();
  const SatChecker checker(s);
  s.start = {0.55, 0.2, 0.0};  // inside a wall
  EXPECT_EQ(planScenario(s, checker, PlanSetup{}).status, PlanStatus::kInvalidStart);
  s = testing::studyLot();
  s.goal.pose = {1.34, 0.04, 0.0};  // on a parked robot
  EXPECT_EQ(planScenario(s, checker, PlanSetup{}).status, PlanStatus::kInvalidGoal);
}

}  // namespace
}  // namespace parksim
