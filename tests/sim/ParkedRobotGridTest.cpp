// The grid that finds parked robots near the robot in worlds with too many to keep in Bullet.

#include "parksim/sim/world/ParkedRobotGrid.h"

#include <gtest/gtest.h>

#include "tests/sim/SimTestSupport.h"

namespace parksim {
namespace {

TEST(ParkedRobotGrid, FindsEveryParkedRobotWithinReachOnceInScenarioOrder) {
  Scenario s = testing::emptyLot();
  testing::addWall(s, "wall", 0.0, 0.0, 0.1, 3.0);             // not a parked robot: never listed
  testing::addParkedRobot(s, "near_b", {0.55, 0.5, 0.3});      // index 1
  testing::addParkedRobot(s, "near_a", {0.45, 0.52, -0.2});    // index 2
  testing::addParkedRobot(s, "far", {5.0, 5.0, 0.0});          // index 3
  testing::addParkedRobot(s, "on_a_corner", {1.0, 1.0, 0.0});  // spans four cells: listed once
  const ParkedRobotGrid grid(s.obstacles, 1.0);
  EXPECT_EQ(grid.cell(), 1.0);
  EXPECT_EQ(grid.near({0.5, 0.5}, 0.2), (std::vector<int>{1, 2, 4}));
  EXPECT_EQ(grid.near({0.5, 0.5}, 1.2), (std::vector<int>{1, 2, 4}));
  EXPECT_EQ(grid.near({5.2, 4.9}, 0.1), (std::vector<int>{3}));
  EXPECT_TRUE(grid.near({-3.0, -3.0}, 0.5).empty());
  // Negative coordinates fall into their own cells, not into cell 0's.
  EXPECT_TRUE(grid.near({-0.5, -0.5}, 0.1).empty());
}

TEST(ParkedRobotGrid, ARobotIsFoundFromEveryCellItsBoxReaches) {
  Scenario s = testing::emptyLot();
  testing::addParkedRobot(s, "straddling", {2.0, 3.0, 0.7});
  const ParkedRobotGrid grid(s.obstacles, 0.5);
  // Its box reaches about 6 cm from its centre (the footprint's half diagonal), across the
  // corner of four cells.
  for (const Eigen::Vector2d& p : {Eigen::Vector2d(1.9, 2.9), Eigen::Vector2d(2.1, 2.9),
                                   Eigen::Vector2d(1.9, 3.1), Eigen::Vector2d(2.1, 3.1)}) {
    EXPECT_EQ(grid.near(p, 0.01), (std::vector<int>{0})) << p.transpose();
  }
}

}  // namespace
}  // namespace parksim
