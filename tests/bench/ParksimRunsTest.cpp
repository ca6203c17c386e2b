// parksim's planners through the benchmark's runner: every planner and steering kind, each path
// checked by the benchmark's exact path check. Budgets are iteration counts only.

#include "bench/planning/ParksimRuns.h"

#include <gtest/gtest.h>

#include <climits>
#include <string>

#include "parksim/collision/BulletCollisionWorld.h"
#include "parksim/scenario/world/ScenarioReader.h"
#include "tests/support/TestPaths.h"

namespace parksim::bench {
namespace {

TEST(ParksimRuns, EveryPlannerAndSteeringGivesACheckedRecord) {
  const Scenario s = loadScenario(parksim::testing::sourceDir() + "/worlds/head_in.yaml");
  const BulletCollisionWorld world(s);
  for (SteeringKind steering : allSteeringKinds()) {
    for (const std::string& kind : builtInPlanners().names()) {
      if (kind == "car-a-star") continue;  // a car's: time-a-star plans this world
      ParksimRunDef def;
      def.setup.steering_kind = steering;
      def.setup.planner = kind;
      def.setup.search.seed = 1;
      def.setup.search.max_iterations = kind == "rrt-star" ? 300 : 2000;
      def.setup.search.record_tree = false;
      def.setup.search.smooth = false;  // "+smooth" records: bench_planning's portfolio
      const BenchRecord r = runParksim(s, world, def);
      SCOPED_TRACE(kind + " / " + toString(steering));
      EXPECT_EQ(r.library, "parksim");
      EXPECT_EQ(r.planner, kind);
      // The A* planners drive their own primitives and curves, whatever the steering.
      EXPECT_EQ(r.space, kind == "hybrid-a-star" ? std::string("primitives+reeds-shepp")
                         : kind == "time-a-star" ? std::string("primitives+balkcom-mason")
                                                 : std::string(toString(steering)));
      EXPECT_EQ(r.scenario, "head_in");
      EXPECT_EQ(r.budget, "iterations=" + std::to_string(def.setup.search.max_iterations));
      EXPECT_GT(r.iterations, -1);
      EXPECT_FALSE(r.phases_s.empty());
      if (!r.solved) continue;  // success rates are the benchmark's business, not this test's
      EXPECT_TRUE(r.valid);
      EXPECT_GT(r.length_m, 0.0);
      EXPECT_GE(r.min_clearance_m, 0.0);
      // time-a-star's cost is the plan's duration; the others' a path cost of at least its length.
      if (kind == "time-a-star") {
        EXPECT_EQ(r.cost, r.duration_s);
        EXPECT_GE(r.duration_s, r.free_space_bound_s);
      } else {
        EXPECT_GE(r.cost, r.length_m);
      }
      EXPECT_GE(r.iterations_first, 0);
    }
  }
}

TEST(ParksimRuns, BudgetNames) {
  SearchDef def;
  def.max_iterations = 2000;
  EXPECT_EQ(budgetName(def), "iterations=2000");
  def.max_time_s = 0.1;
  EXPECT_EQ(budgetName(def), "iterations=2000+time=0.1s");
  def.max_iterations = INT_MAX;
  EXPECT_EQ(budgetName(def), "time=0.1s");
}

}  // namespace
}  // namespace parksim::bench
