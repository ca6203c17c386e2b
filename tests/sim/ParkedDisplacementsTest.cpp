// How far parked robots were pushed: only those given mass are read, and a push is measured.

#include "parksim/sim/episode/ParkedDisplacements.h"

#include <cstdio>

#include <gtest/gtest.h>

#include "tests/sim/SimTestSupport.h"

namespace parksim {
namespace {

TEST(ParkedDisplacements, ListsEveryParkedRobotAndMeasuresThePushedOne) {
  Scenario s = testing::emptyLot({0.5, 0.5, 0.0});
  testing::addWall(s, "wall", 1.8, 0.0, 1.9, 2.0);
  testing::addParkedRobot(s, "ahead", {0.62, 0.5, 0.0});  // 40 mm in front of the robot
  testing::addParkedRobot(s, "far", {1.5, 1.5, 0.0});
  DynamicsWorld world(s, s.start);
  ParkedDisplacements parked(s.obstacles, world.obstaclePoses());
  ASSERT_EQ(parked.all().size(), 2u);
  EXPECT_EQ(parked.all()[0].name, "ahead");
  EXPECT_EQ(parked.all()[1].name, "far");
  world.setWheelTargets({6.0, 6.0});
  for (int k = 0; k < 240; ++k) {
    world.step();
    parked.update(world);
  }
  // The robot reaches the parked one within 0.5 s and pushes it; how far is chaotic
  // (docs/simulation.md), that it moved is not.
  std::printf("pushed %.3f mm (final %.3f mm)\n", parked.all()[0].max_m * 1e3,
              parked.all()[0].final_m * 1e3);
  EXPECT_GT(parked.all()[0].max_m, 0.001);
  EXPECT_GE(parked.all()[0].max_m, parked.all()[0].final_m);
  EXPECT_EQ(parked.all()[1].max_m, 0.0);
  EXPECT_EQ(parked.max(), parked.all()[0].max_m);
}

}  // namespace
}  // namespace parksim
