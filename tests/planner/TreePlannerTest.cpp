#include "parksim/planner/tree/TreePlanner.h"

#include <string>

#include <gtest/gtest.h>

#include "parksim/core/io/Error.h"
#include "parksim/planner/base/PlanScenario.h"
#include "tests/support/PlanChecks.h"
#include "tests/support/StudyLot.h"
#include "tests/support/TreePlannerSetup.h"

namespace parksim {
namespace {

using testing::expectTreeRecorded;
using testing::expectValidPlan;
using testing::SatChecker;
using testing::treeSetupFor;

// Each planner's solve rate over seeds on the study lot: TreePlannerStudyLotTest.cpp (run once,
// in the Release pass).

TEST(TreePlanner, RrtStarCostNeverIncreasesAndEndsNoWorseThanItsFirstSolution) {
  int improved = 0;
  for (bool parallel : {false, true}) {
    const Scenario s = parallel ? testing::studyLotParallel() : testing::studyLot();
    const SatChecker checker(s);
    for (SteeringKind steering : allSteeringKinds()) {
      for (int seed = 1; seed <= 3; ++seed) {
        SCOPED_TRACE(std::string(toString(steering)) + (parallel ? " parallel" : " head-in") +
                     " seed " + std::to_string(seed));
        PlanSetup setup = treeSetupFor("rrt-star", steering, seed);
        setup.search.max_iterations = 250;
        setup.planner_params["informed_sampling"] = seed != 3 ? "true" : "false";  // plain RRT* too
        const PlanResult r = planScenario(s, checker, setup);
        expectValidPlan(s, checker, setup, r);
        EXPECT_EQ(r.stats.iterations, 250);  // anytime: the whole budget
        const std::vector<CostSample>& h = r.cost_history;
        for (std::size_t i = 1; i < h.size(); ++i) {
          EXPECT_LE(h[i].cost, h[i - 1].cost);
          EXPECT_GE(h[i].iteration, h[i - 1].iteration);
          EXPECT_GE(h[i].time_s, h[i - 1].time_s);
        }
        EXPECT_EQ(h.front().iteration, r.stats.first_solution_iteration);
        EXPECT_LE(r.cost, h.front().cost);
        if (r.cost < h.front().cost - 1e-6) ++improved;
      }
    }
  }
  EXPECT_GE(improved, 6);  // it does improve, not just keep its first solution
}

TEST(TreePlanner, RrtConnectGoalTreeEdgesRunForwardToTheirParents) {
  const Scenario s = testing::studyLotParallel();
  const SatChecker checker(s);
  int grown = 0;
  for (SteeringKind steering : allSteeringKinds()) {
    for (int seed = 1; seed <= 10; ++seed) {
      const PlanSetup setup = treeSetupFor("rrt-connect", steering, seed);
      const PlanResult r = planScenario(s, checker, setup);
      SCOPED_TRACE("seed " + std::to_string(seed));
      expectValidPlan(s, checker, setup, r);
      // Goal-tree edges are recorded after the start tree's. Each one starts at rest at its
      // child, integrates forward in time, and ends exactly where its parent's edge starts, or
      // in the goal region at a root.
      const auto first = r.tree_edges.begin() + (r.stats.tree_size - 1);
      for (auto e = first; e != r.tree_edges.end(); ++e) {
        testing::expectConsistentWithLimits(*e, s.robot, {}, 1e-12);
        const Pose2& end = e->points.back().pose;
        bool joins = positionDistance(end, s.goal.pose) <= s.goal.position_tolerance_m &&
                     headingDistance(end, s.goal.pose) <= s.goal.heading_tolerance_rad;
        for (auto other = first; other != r.tree_edges.end() && !joins; ++other) {
          joins = other->points.front().pose == end;
        }
        EXPECT_TRUE(joins);
      }
      if (r.stats.goal_tree_size > 1) ++grown;
      EXPECT_GT(r.stats.connection_attempts, 0);
    }
  }
  EXPECT_GE(grown, 5);
}

TEST(TreePlanner, SmoothingNeverMakesAPlanSlowerAndKeepsItValid) {
  int improved = 0;
  for (bool parallel : {false, true}) {
    const Scenario s = parallel ? testing::studyLotParallel() : testing::studyLot();
    const SatChecker checker(s);
    for (const std::string& kind : builtInPlanners().names()) {
      // Not tree planners: HardWorldsPlanningTest.cpp, TimeAStarTest.cpp.
      if (kind == "hybrid-a-star" || kind == "time-a-star" || kind == "car-a-star") continue;
      for (SteeringKind steering : allSteeringKinds()) {
        for (int seed = 1; seed <= 2; ++seed) {
          SCOPED_TRACE(std::string(kind) + " " + toString(steering) + " seed " +
                       std::to_string(seed));
          PlanSetup setup = treeSetupFor(kind, steering, seed);
          if (kind == "rrt-star") setup.search.max_iterations = 60;
          const PlanResult plain = planScenario(s, checker, setup);
          setup.search.smooth = true;
          setup.search.smoothing_attempts = 40;
          const PlanResult smoothed = planScenario(s, checker, setup);
          ASSERT_EQ(plain.solved(), smoothed.solved());
          if (!plain.solved()) continue;
          expectValidPlan(s, checker, setup, smoothed);
          // Smoothing minimises the time-optimal duration (PathSmoother.h).
          EXPECT_LE(smoothed.trajectory.duration(), plain.trajectory.duration() + 1e-9);
          // Smoothing runs after the search, which is unchanged.
          ASSERT_GE(smoothed.cost_history.size(), plain.cost_history.size());
          for (std::size_t i = 0; i + 1 < plain.cost_history.size(); ++i) {
            EXPECT_EQ(smoothed.cost_history[i].cost, plain.cost_history[i].cost);
          }
          if (smoothed.trajectory.duration() < plain.trajectory.duration() - 1e-6) {
            ++improved;
            EXPECT_GT(smoothed.stats.smoothing_shortcuts + smoothed.stats.smoothing_fillets, 0);
          }
        }
      }
    }
  }
  EXPECT_GE(improved, 10);
}

TEST(TreePlanner, SameSeedSameResultForEveryPlannerAndSteering) {
  const Scenario s = testing::studyLotParallel();
  const SatChecker checker(s);
  for (const std::string& kind : builtInPlanners().names()) {
    // Not tree planners: HardWorldsPlanningTest.cpp, TimeAStarTest.cpp.
    if (kind == "hybrid-a-star" || kind == "time-a-star" || kind == "car-a-star") continue;
    for (SteeringKind steering : allSteeringKinds()) {
      SCOPED_TRACE(std::string(kind) + " " + toString(steering));
      PlanSetup setup = treeSetupFor(kind, steering, 11);
      if (kind == "rrt-star") setup.search.max_iterations = 80;
      setup.search.smooth = true;
      const PlanResult a = planScenario(s, checker, setup);
      const PlanResult b = planScenario(s, checker, setup);
      ASSERT_TRUE(a.solved());
      EXPECT_EQ(a.trajectory, b.trajectory);
      EXPECT_EQ(a.cost, b.cost);
      EXPECT_EQ(a.waypoints.size(), b.waypoints.size());
      EXPECT_EQ(a.tree_edges, b.tree_edges);
      EXPECT_EQ(a.stats.iterations, b.stats.iterations);
      EXPECT_EQ(a.cost_history.size(), b.cost_history.size());
    }
  }
}

TEST(TreePlanner, ProgressCountsEveryIterationUpToTheResult) {
  // Every planner reports each iteration (node expansion for hybrid-a-star) once, in order,
  // against its budget; the last report is the result's own count.
  const Scenario s = testing::studyLot();
  const SatChecker checker(s);
  for (const std::string& kind : builtInPlanners().names()) {
    SCOPED_TRACE(kind);
    PlanSetup setup = treeSetupFor(kind, SteeringKind::kReedsShepp, 3);
    if (kind == "rrt-star") setup.search.max_iterations = 60;
    std::vector<long> done;
    long budget = -1;
    const PlanResult r = planScenario(s, checker, setup, [&](long d, long b) {
      done.push_back(d);
      budget = b;
    });
    ASSERT_FALSE(done.empty());
    EXPECT_EQ(budget, setup.search.max_iterations);
    for (std::size_t i = 0; i < done.size(); ++i) EXPECT_EQ(done[i], static_cast<long>(i) + 1);
    EXPECT_EQ(done.back(), r.stats.iterations);
    // The callback only watches: the plan is the one made without it.
    EXPECT_EQ(planScenario(s, checker, setup).trajectory, r.trajectory);
  }
}

TEST(TreePlanner, OtherSeedOtherTrajectory) {
  const Scenario s = testing::studyLotParallel();
  const SatChecker checker(s);
  PlanSetup setup;
  setup.planner = "rrt-goal-connect";  // PlanSetup's default uses no randomness
  // Balkcom-Mason steering reaches the parallel goal at the first goal check, whatever the seed.
  setup.steering_kind = SteeringKind::kReedsShepp;
  setup.search.seed = 11;
  const PlanResult a = planScenario(s, checker, setup);
  setup.search.seed = 12;
  const PlanResult c = planScenario(s, checker, setup);
  ASSERT_TRUE(a.solved());
  ASSERT_TRUE(c.solved());
  EXPECT_NE(a.trajectory, c.trajectory);
}

TEST(TreePlanner, EitherHeadingGoalAcceptsHeadInAndBackIn) {
  // The study's head-in bay, asked for backing in (heading +90 degrees) or heading in.
  Scenario s = testing::studyLot();
  s.goal.pose.theta = degToRad(90);
  s.goal.either_heading = true;
  const SatChecker checker(s);
  for (const std::string& kind : builtInPlanners().names()) {
    // Not tree planners: HardWorldsPlanningTest.cpp, TimeAStarTest.cpp.
    if (kind == "hybrid-a-star" || kind == "time-a-star" || kind == "car-a-star") continue;
    for (SteeringKind steering : allSteeringKinds()) {
      int solved = 0;
      for (int seed = 1; seed <= 4; ++seed) {
        SCOPED_TRACE(std::string(kind) + " " + toString(steering) + " seed " +
                     std::to_string(seed));
        PlanSetup setup = treeSetupFor(kind, steering, seed);
        if (kind == "rrt-star") setup.search.max_iterations = 80;
        const PlanResult r = planScenario(s, checker, setup);
        if (!r.solved()) continue;
        ++solved;
        expectValidPlan(s, checker, setup, r);  // ends within tolerance of either heading
        expectTreeRecorded(r, 2);
      }
      EXPECT_GE(solved, kind == "rrt" ? 2 : 4) << kind;
    }
  }
}

TEST(TreePlanner, EitherHeadingEndsTurnedWhenOnlyTheTurnedGoalIsFree) {
  // The body reaches 70 mm behind the reference point and 10 mm ahead of it: with a post 45 mm
  // behind the goal, only the turned goal pose is free.
  Scenario s;
  s.start = {0.3, 0.6, 0.0};
  s.goal.pose = {1.2, 0.6, 0.0};
  Obstacle post;
  post.name = "post";
  post.box.center = {1.2 - 0.045 - 0.02, 0.6};
  post.box.half_extents = {0.02, 0.02};
  s.obstacles.push_back(post);
  const SatChecker checker(s);
  EXPECT_EQ(planScenario(s, checker, PlanSetup{}).status, PlanStatus::kInvalidGoal);
  s.goal.either_heading = true;
  for (const std::string& kind : builtInPlanners().names()) {
    // Not tree planners: HardWorldsPlanningTest.cpp, TimeAStarTest.cpp.
    if (kind == "hybrid-a-star" || kind == "time-a-star" || kind == "car-a-star") continue;
    for (SteeringKind steering : allSteeringKinds()) {
      SCOPED_TRACE(std::string(kind) + " " + toString(steering));
      PlanSetup setup = treeSetupFor(kind, steering, 3);
      if (kind == "rrt-star") setup.search.max_iterations = 60;
      const PlanResult r = planScenario(s, checker, setup);
      expectValidPlan(s, checker, setup, r);
      EXPECT_NEAR(std::abs(r.trajectory.points.back().pose.theta), kPi,
                  s.goal.heading_tolerance_rad);
    }
  }
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
  for (const std::string& kind : builtInPlanners().names()) {
    PlanSetup setup;
    setup.planner = kind;
    setup.search.max_iterations = kind == "rrt-star" ? 100 : 300;
    const PlanResult r = planScenario(s, checker, setup);
    EXPECT_EQ(r.status, PlanStatus::kIterationLimit) << kind;
    EXPECT_TRUE(r.trajectory.empty());
    EXPECT_TRUE(r.cost_history.empty());
    // time-a-star (which plans for a differential drive when car-a-star is asked for) may run
    // out of cells to expand first: the fenced row is a small space.
    if (kind == "time-a-star" || kind == "car-a-star") {
      EXPECT_LE(r.stats.iterations, setup.search.max_iterations);
    } else {
      EXPECT_EQ(r.stats.iterations, setup.search.max_iterations);
    }
    EXPECT_EQ(r.stats.first_solution_s, -1.0);
  }
}

TEST(TreePlanner, InvalidStartAndGoalAreStatuses) {
  Scenario s = testing::studyLot();
  const SatChecker checker(s);
  s.start = {0.55, 0.2, 0.0};  // inside a wall
  EXPECT_EQ(planScenario(s, checker, PlanSetup{}).status, PlanStatus::kInvalidStart);
  s = testing::studyLot();
  s.goal.pose = {1.34, 0.04, 0.0};  // on a parked robot
  EXPECT_EQ(planScenario(s, checker, PlanSetup{}).status, PlanStatus::kInvalidGoal);
  s.goal.either_heading = true;  // turned, it is on the parked robot too
  EXPECT_EQ(planScenario(s, checker, PlanSetup{}).status, PlanStatus::kInvalidGoal);
  EXPECT_EQ(planScenario(s, checker, PlanSetup{}).message,
            "goal: robot footprint overlaps obstacle \"robot_5\" (in both accepted headings)");
}

// The reader's rule, applied by the planner too: a start 0.3 mm from an obstacle is refused
// naming the margin (not "collides"), a goal on the lot edge likewise, and low obstacles are
// not obstacles.
TEST(TreePlanner, StartAndGoalFollowThePlacementRule) {
  Scenario s = testing::studyLot();
  const double front = s.start.y + s.robot.front_overhang_m;  // facing +y
  s.obstacles.push_back(Obstacle::makeBox("near", ObstacleKind::kBox,
                                          testing::cornerBox(0.0, front + 0.0003, 0.3, 0.05), 0.1));
  SatChecker checker(s);
  PlanResult r = planScenario(s, checker, PlanSetup{});
  EXPECT_EQ(r.status, PlanStatus::kInvalidStart);
  EXPECT_EQ(r.message,
            "start: robot footprint is 0.3 mm from obstacle \"near\"; start and goal keep at "
            "least the 0.5 mm margin of the planner's motion checks");
  EXPECT_EQ(r.message, "start: " + *placementProblem(s, s.start));
  s.obstacles.back().height_m = 0.001;  // under the 2 mm ground clearance
  EXPECT_FALSE(placementProblem(s, s.start).has_value());
  s = testing::studyLot();
  s.goal.pose.y = s.lot.y_min_m;
  checker = SatChecker(s);
  r = planScenario(s, checker, PlanSetup{});
  EXPECT_EQ(r.status, PlanStatus::kInvalidGoal);
  EXPECT_NE(r.message.find("closer than the 0.5 mm margin to the lot edge"), std::string::npos)
      << r.message;
  // Rounding within 1 nm of the margin is forgiven by the tree search's own checks too: such a
  // start passed the reader and was refused as "within half the motion-check resolution".
  s = testing::studyLot();
  s.start.x = s.lot.x_min_m + kPlacementMargin_m - 1e-10;
  ASSERT_FALSE(placementProblem(s, s.start).has_value());
  for (const std::string kind : {"rrt-goal-connect", "hybrid-a-star"}) {
    PlanSetup setup;
    setup.planner = kind;
    setup.search.max_iterations = 50;
    r = planScenario(s, checker, setup);
    EXPECT_NE(r.status, PlanStatus::kInvalidStart) << kind << ": " << r.message;
  }
}

TEST(TreePlanner, AStartOnTheLotEdgeIsNotReportedAsACollision) {
  Scenario s = testing::studyLot();
  const SatChecker checker(s);
  s.start = {0.1, 0.0002, kPi / 2};  // nothing there, but 0.2 mm from the edge y = 0
  const PlanResult r = planScenario(s, checker, PlanSetup{});
  EXPECT_EQ(r.status, PlanStatus::kInvalidStart);
  EXPECT_EQ(r.message,
            "start: reference point (0.1, 2e-04) is closer than the 0.5 mm margin to the lot edge "
            "[0, 1.8] x [0, 1.2]");
  s.start = {0.55, 0.2, 0.0};  // inside a wall
  EXPECT_EQ(planScenario(s, checker, PlanSetup{}).message,
            "start: robot footprint overlaps obstacle \"wall_2\"");
}

TEST(TreePlanner, SteeringNamesRoundTripAndUnknownNamesThrow) {
  for (SteeringKind kind : allSteeringKinds()) {
    EXPECT_EQ(steeringKindFromString(toString(kind)), kind);
  }
  EXPECT_STREQ(toString(SteeringKind::kReedsShepp), "reeds-shepp");
  EXPECT_STREQ(toString(SteeringKind::kBalkcomMason), "balkcom-mason");
  EXPECT_THROW(steeringKindFromString("dubins"), Error);
}

TEST(TreePlanner, RejectsBadDefinitions) {
  const Scenario s = testing::studyLot();
  const SatChecker checker(s);
  // The tree planner's definition (PlanSetup's default planner is time-a-star).
  PlanSetup setup;
  setup.planner = "rrt-goal-connect";
  setup.planner_params["extend_distance_m"] = "-1";
  EXPECT_THROW(planScenario(s, checker, setup), Error);
  setup = {};
  setup.planner = "rrt-goal-connect";
  setup.search.cusp_penalty_m = -1.0;
  EXPECT_THROW(planScenario(s, checker, setup), Error);
  setup = {};
  setup.planner = "rrt-goal-connect";
  setup.search.smoothing_attempts = -1;
  EXPECT_THROW(planScenario(s, checker, setup), Error);
}

}  // namespace
}  // namespace parksim
