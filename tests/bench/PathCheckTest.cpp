// parksim's exact path check: dense sampling, lot bounds, overlaps, clearance, cusps.

#include "bench/planning/PathCheck.h"

#include <gtest/gtest.h>

#include "parksim/collision/BulletCollisionWorld.h"
#include "parksim/core/geometry/Angle.h"
#include "parksim/core/model/Geometry.h"
#include "parksim/scenario/world/ScenarioReader.h"
#include "tests/support/TestPaths.h"

namespace parksim::bench {
// Named, not anonymous: its program is compiled as one unity batch, where another file's
// helpers of the same names would meet these.
namespace path_check_test {

Scenario headIn() { return loadScenario(parksim::testing::sourceDir() + "/worlds/head_in.yaml"); }

// Poses along a straight line, `step` apart, heading along the line.
std::vector<Pose2> line(Pose2 from, double length, double step) {
  std::vector<Pose2> poses;
  const int n = static_cast<int>(std::ceil(length / step));
  for (int k = 0; k <= n; ++k) {
    const double s = length * k / n;
    poses.push_back(
        {from.x + s * std::cos(from.theta), from.y + s * std::sin(from.theta), from.theta});
  }
  return poses;
}

TEST(PathCheck, FreeStraightPathIsValidWithItsClearance) {
  const Scenario s = headIn();
  const BulletCollisionWorld world(s);
  // Up the west side of the lot, x = 0.2: the nearest obstacle is wall_2 at x = 0.5.
  const std::vector<Pose2> poses = line({0.2, 0.1, kPi / 2}, 0.9, 0.0001);
  const PathCheck check = checkPath(poses, s, world);
  EXPECT_TRUE(check.dense_enough);
  EXPECT_TRUE(check.valid);
  EXPECT_NEAR(check.length_m, 0.9, 1e-9);
  // Footprint half width 42.5 mm: its side is at x = 0.2425, 0.2575 m from the wall.
  EXPECT_NEAR(check.min_clearance_m, 0.5 - 0.2425, 1e-6);
}

TEST(PathCheck, PathThroughAnObstacleIsInvalidAtItsFirstOverlap) {
  const Scenario s = headIn();
  const BulletCollisionWorld world(s);
  // Eastward along y = 0.65, straight through the island (x 0.8..1.6, y 0.6..0.7).
  const std::vector<Pose2> poses = line({0.7, 0.65, 0.0}, 0.4, 0.0001);
  const PathCheck check = checkPath(poses, s, world);
  EXPECT_TRUE(check.dense_enough);
  EXPECT_FALSE(check.valid);
  ASSERT_LT(check.first_bad, poses.size());
  // The front edge is 10 mm ahead of the reference point: first overlap just past x = 0.79.
  EXPECT_NEAR(poses[check.first_bad].x, 0.79, 0.0002);
  EXPECT_EQ(check.min_clearance_m, 0.0);
}

TEST(PathCheck, ThinObstacleBetweenSparsePosesIsNotTrusted) {
  const Scenario s = headIn();
  const BulletCollisionWorld world(s);
  // Both ends are free, but the 0.1 m wall lies between them: a sparse path must be rejected
  // for its density, whatever its end poses say.
  const std::vector<Pose2> poses = {{0.3, 0.2, 0.0}, {0.8, 0.2, 0.0}};
  ASSERT_TRUE(world.isFree(poses[0]));
  ASSERT_TRUE(world.isFree(poses[1]));
  const PathCheck check = checkPath(poses, s, world);
  EXPECT_FALSE(check.dense_enough);
  EXPECT_FALSE(check.valid);
}

TEST(PathCheck, LeavingTheLotIsInvalid) {
  const Scenario s = headIn();
  const BulletCollisionWorld world(s);
  const std::vector<Pose2> poses = line({0.2, 0.3, kPi}, 0.3, 0.0001);  // west past x = 0
  const PathCheck check = checkPath(poses, s, world);
  EXPECT_FALSE(check.valid);
  ASSERT_LT(check.first_bad, poses.size());
  EXPECT_LT(poses[check.first_bad].x, 0.0);
}

TEST(PathCheck, DensifyBoundsTheFootprintStepAndKeepsTheEnds) {
  const RobotDef robot;
  Trajectory traj;
  // Half a second of an arc, then half a second turning in place, then the stop.
  traj.points.push_back({0.0, {0.3, 0.3, 0.0}, toWheelSpeeds({0.05, 1.0}, robot)});
  const Pose2 p1 = integrateExact(traj.points[0].pose, {0.05, 1.0}, 0.5);
  traj.points.push_back({0.5, p1, toWheelSpeeds({0.0, 2.0}, robot)});
  const Pose2 p2 = integrateExact(p1, {0.0, 2.0}, 0.5);
  traj.points.push_back({1.0, p2, {}});
  const std::vector<Pose2> dense = densify(traj, robot, 0.0002);
  ASSERT_GT(dense.size(), 100u);
  EXPECT_EQ(dense.front(), traj.points.front().pose);
  EXPECT_EQ(dense.back(), p2);
  for (std::size_t i = 1; i < dense.size(); ++i) {
    EXPECT_LE(footprintStep(dense[i - 1], dense[i], footprintRadius(robot)), 0.0002 + 1e-12);
  }
}

TEST(PathCheck, CuspsCountReversalsButNotTurningInPlace) {
  std::vector<Pose2> poses = line({0.2, 0.2, 0.0}, 0.1, 0.001);                    // forward
  for (int k = 1; k <= 20; ++k) poses.push_back({poses.back().x, 0.2, 0.05 * k});  // turn
  const Pose2 end = poses.back();
  for (int k = 1; k <= 50; ++k) {  // backward along the new heading
    poses.push_back({end.x - 0.001 * k * std::cos(end.theta),
                     end.y - 0.001 * k * std::sin(end.theta), end.theta});
  }
  EXPECT_EQ(countCusps(poses), 1);
  EXPECT_EQ(countCusps(line({0.2, 0.2, 0.0}, 0.1, 0.001)), 0);
}

}  // namespace path_check_test
}  // namespace parksim::bench
