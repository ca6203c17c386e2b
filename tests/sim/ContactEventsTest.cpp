// Contact events from per-step touches: flicker within the merge time is one event.

#include "parksim/sim/episode/ContactEvents.h"

#include <gtest/gtest.h>

#include "tests/sim/SimTestSupport.h"

namespace parksim {
namespace {

TEST(ContactEventMerger, TouchesWithinTheMergeTimeAreOneEventAndLaterOnesAnother) {
  Scenario s = testing::emptyLot();
  testing::addParkedRobot(s, "robot_1", {1.0, 1.0, 0.0});
  testing::addWall(s, "wall_1", 0.0, 0.0, 0.1, 1.0);
  ContactEventMerger merger(s.obstacles.size(), 24);
  const double dt = 1.0 / 240.0;
  auto at = [&](long k, const std::vector<int>& touching) {
    merger.add(k, static_cast<double>(k) * dt, touching, s.obstacles);
  };
  at(10, {0});
  at(11, {0});
  at(20, {});
  at(35, {0});     // 24 steps after its last touch: the same event
  at(60, {0, 1});  // 25 steps after: a new event, and the wall's first
  at(61, {1});
  ASSERT_EQ(merger.events().size(), 3u);
  EXPECT_EQ(merger.events()[0].obstacle_index, 0);
  EXPECT_EQ(merger.events()[0].body, "robot_1");
  EXPECT_DOUBLE_EQ(merger.events()[0].t_s, 10 * dt);
  EXPECT_DOUBLE_EQ(merger.events()[1].t_s, 60 * dt);
  EXPECT_EQ(merger.events()[1].body, "robot_1");
  EXPECT_EQ(merger.events()[2].body, "wall_1");
  EXPECT_DOUBLE_EQ(merger.events()[2].t_s, 60 * dt);
}

// Without a merge time every touching step is an event of its own: the next step is already
// one step after the last touch.
TEST(ContactEventMerger, WithoutAMergeTimeEveryTouchingStepIsAnEvent) {
  Scenario s = testing::emptyLot();
  testing::addWall(s, "wall_1", 0.0, 0.0, 0.1, 1.0);
  ContactEventMerger merger(1, 0);
  merger.add(1, 0.1, {0}, s.obstacles);
  merger.add(2, 0.2, {0}, s.obstacles);
  merger.add(4, 0.4, {0}, s.obstacles);
  EXPECT_EQ(merger.events().size(), 3u);
}

}  // namespace
}  // namespace parksim
