// The default budget from the free area a search can reach: an empty lot's is its area, a room
// walled off from the rest is the room's, and only the A* planners follow it.

#include "parksim/planner/search/ReachableBudget.h"

#include <cmath>

#include <gtest/gtest.h>

#include "parksim/planner/base/PlannerRegistry.h"

namespace parksim {
namespace {

int budget(const char* planner, const Scenario& s) {
  return defaultIterationBudget(builtInPlanners().find(planner).info, s);
}

Scenario emptyLot(double side) {
  Scenario s;
  s.lot = {0.0, 0.0, side, side};
  s.start = {0.5, 0.5, 0.0};
  s.goal.pose = {0.6, 0.5, 0.0};
  return s;
}

Obstacle wall(const std::string& name, double x0, double y0, double x1, double y1) {
  OrientedBox b;
  b.center = {0.5 * (x0 + x1), 0.5 * (y0 + y1)};
  b.half_extents = {0.5 * (x1 - x0), 0.5 * (y1 - y0)};
  return Obstacle::makeBox(name, ObstacleKind::kWall, b, 0.1);
}

TEST(ReachableBudget, AnEmptyLotIsAllReachableAndTimeAStarGetsEightExpansionsPerCell) {
  const Scenario s = emptyLot(4.0);
  EXPECT_NEAR(reachableFreeArea(s), 16.0, 1e-9);
  const double cell = 0.25 * footprintRadius(s.robot);
  EXPECT_EQ(budget("time-a-star", s), static_cast<int>(std::ceil(8.0 * 16.0 / (cell * cell))));
  EXPECT_EQ(budget("hybrid-a-star", s),
            static_cast<int>(std::ceil(20000.0 * 16.0 / kStudyLotAreaM2)));
  // The tree planners sample the whole lot: the lot's budget.
  EXPECT_EQ(budget("rrt-connect", s), lotScaledBudget(2000, s));
}

TEST(ReachableBudget, AWalledRoomIsAllTheSearchCanReach) {
  Scenario s = emptyLot(4.0);
  // A 1 x 1 m room around the start, walls 5 cm thick.
  s.obstacles = {wall("s", 0.0, 0.0, 1.1, 0.05), wall("n", 0.0, 1.05, 1.1, 1.1),
                 wall("w", 0.0, 0.0, 0.05, 1.1), wall("e", 1.05, 0.0, 1.1, 1.1)};
  const double room = reachableFreeArea(s);
  EXPECT_GT(room, 0.5);
  EXPECT_LT(room, 1.3);
  // Far below the open lot's: the lot's own budget is the floor.
  EXPECT_EQ(budget("time-a-star", s), 200000);
  // Open a door: the rest of the lot joins.
  s.obstacles[3] = wall("e", 1.05, 0.0, 1.1, 0.4);
  EXPECT_GT(reachableFreeArea(s), 14.0);
  EXPECT_GT(budget("time-a-star", s), 200000);
}

TEST(ReachableBudget, IsCappedAtTheLargestIterationBudget) {
  EXPECT_EQ(budget("time-a-star", emptyLot(100.0)), 1000000);
}

}  // namespace
}  // namespace parksim
