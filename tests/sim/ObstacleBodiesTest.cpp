// Obstacles as bodies of the dynamics world: a compound obstacle is solid where its parts are
// and open where the polygon is, not its convex hull.

#include "parksim/sim/world/ObstacleBodies.h"

#include <gtest/gtest.h>

#include "parksim/core/geometry/ConvexPartition.h"
#include "parksim/sim/world/DynamicsWorld.h"
#include "tests/sim/SimTestSupport.h"

namespace parksim {
namespace {

TEST(ObstacleBodies, ARobotDrivesIntoANonConvexObstaclesNotchUntilItsBackWall) {
  Scenario s = testing::emptyLot({0.5, 0.5, 0.0});
  // A U opening toward the robot: arms from x = 0.7, the back wall from x = 0.95.
  const PolygonWithHoles u{{{0.7, 0.3},
                            {1.0, 0.3},
                            {1.0, 0.7},
                            {0.7, 0.7},
                            {0.7, 0.58},
                            {0.95, 0.58},
                            {0.95, 0.42},
                            {0.7, 0.42}},
                           {}};
  s.obstacles.push_back(Obstacle::makeCompound(
      "u", ObstacleKind::kWall, CompoundShape::make(convexPartition(u), {u.outer}), 0.1));
  DynamicsWorld world(s, s.start);
  world.setWheelTargets({5.0, 5.0});  // 0.1 m/s straight ahead
  double first_contact_x = -1.0;
  for (int k = 0; k < 6 * 240 && first_contact_x < 0.0; ++k) {
    world.step();
    if (!world.chassisContacts().empty()) {
      EXPECT_EQ(world.chassisContacts(), std::vector<int>{0});
      first_contact_x = world.robot().pose.x;
    }
  }
  // The front edge (10 mm ahead of the reference point) meets the back wall, not the opening
  // its convex hull would close.
  EXPECT_NEAR(first_contact_x + s.robot.front_overhang_m, 0.95, 0.002);
}

}  // namespace
}  // namespace parksim
