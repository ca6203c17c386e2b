// OMPL on the study lot through parksim's footprint checker, one forked child per run. The runs
// end on OMPL's exact solution (RRTConnect stops at its first one); the time limit is only a
// safety net and no test looks at a time.

#include "bench/ompl/OmplPlanners.h"

#include <gtest/gtest.h>

#include "parksim/collision/BulletCollisionWorld.h"
#include "parksim/core/io/Error.h"
#include "parksim/scenario/world/ScenarioReader.h"
#include "tests/support/TestPaths.h"

namespace parksim::bench {
namespace {

Scenario headIn() { return loadScenario(parksim::testing::sourceDir() + "/worlds/head_in.yaml"); }

OmplRunDef easyQuery(std::uint32_t seed) {
  OmplRunDef def;
  def.planner = OmplPlanner::kRrtConnect;
  def.space = OmplSpace::kReedsShepp;
  def.seed = seed;
  def.time_limit_s = 120.0;  // safety net only: RRTConnect returns at its exact solution
  return def;
}

TEST(OmplPlanners, ReedsSheppPathOnTheStudyLotPassesTheExactCheck) {
  const Scenario s = headIn();
  const BulletCollisionWorld world(s);
  const OmplRunResult run = runOmplForked(s, world, easyQuery(1));
  ASSERT_TRUE(run.solved) << run.status;
  EXPECT_EQ(run.status, "Exact solution");
  ASSERT_GE(run.waypoints.size(), 2u);
  EXPECT_EQ(run.waypoints.front(), s.start);
  EXPECT_EQ(run.dense.front(), s.start);
  EXPECT_LT(positionDistance(run.dense.back(), s.goal.pose), 1e-3);

  const PathCheck check = checkPath(run.dense, s, world);
  EXPECT_TRUE(check.dense_enough) << check.max_step_m;
  EXPECT_TRUE(check.valid) << "first overlap at pose " << check.first_bad;
  EXPECT_GT(check.min_clearance_m, 0.0);
  // Reeds-Shepp arcs: the polyline through the dense poses is the path's length.
  EXPECT_NEAR(check.length_m, run.ompl_length, 1e-3 * run.ompl_length);
}

TEST(OmplPlanners, RecordCarriesTheCheckedPath) {
  const Scenario s = headIn();
  const BulletCollisionWorld world(s);
  const BenchRecord r = runOmpl(s, world, easyQuery(3));
  EXPECT_EQ(r.library, "ompl");
  EXPECT_EQ(r.planner, "RRTConnect");
  EXPECT_EQ(r.space, "reeds-shepp");
  EXPECT_EQ(r.scenario, "head_in");
  EXPECT_EQ(r.seed, 3u);
  EXPECT_TRUE(r.solved);
  EXPECT_TRUE(r.valid);
  EXPECT_GT(r.length_m, positionDistance(s.start, s.goal.pose));
  EXPECT_GE(r.cusps, 0);
  EXPECT_GT(r.tree_size, 1);
}

TEST(OmplPlanners, SameSeedSamePathOtherSeedOtherPath) {
  const Scenario s = headIn();
  const BulletCollisionWorld world(s);
  const OmplRunResult a = runOmplForked(s, world, easyQuery(5));
  const OmplRunResult b = runOmplForked(s, world, easyQuery(5));
  const OmplRunResult c = runOmplForked(s, world, easyQuery(6));
  ASSERT_TRUE(a.solved && b.solved && c.solved);
  EXPECT_EQ(a.waypoints, b.waypoints);
  EXPECT_EQ(a.dense, b.dense);
  EXPECT_EQ(a.graph_states, b.graph_states);
  EXPECT_NE(a.waypoints, c.waypoints);
}

TEST(OmplPlanners, Se2RunsToo) {
  const Scenario s = headIn();
  const BulletCollisionWorld world(s);
  OmplRunDef def = easyQuery(2);
  def.space = OmplSpace::kSe2;
  const OmplRunResult run = runOmplForked(s, world, def);
  ASSERT_TRUE(run.solved) << run.status;
  EXPECT_TRUE(checkPath(run.dense, s, world).dense_enough);
}

TEST(OmplPlanners, RejectsSeedZeroAndUnknownNames) {
  const Scenario s = headIn();
  const BulletCollisionWorld world(s);
  EXPECT_THROW(runOmplForked(s, world, easyQuery(0)), Error);
  EXPECT_THROW(omplPlannerFromString("PRM"), Error);
  EXPECT_EQ(omplSpaceFromString("se2"), OmplSpace::kSe2);
  EXPECT_EQ(omplPlannerFromString("RRTstar"), OmplPlanner::kRrtStar);
}

}  // namespace
}  // namespace parksim::bench
