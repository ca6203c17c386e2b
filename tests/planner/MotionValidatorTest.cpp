#include "parksim/planner/motion/MotionValidator.h"

#include <random>

#include <gtest/gtest.h>

#include "tests/support/StudyLot.h"

namespace parksim {
namespace {

using testing::SatChecker;

const LotBounds kOpenLot{-10.0, -10.0, 10.0, 10.0};

Scenario oneThinWall(double x_center, double thickness) {
  Scenario s;
  Obstacle wall;
  wall.name = "thin";
  wall.box.center = {x_center, 0.5};
  wall.box.half_extents = {0.5 * thickness, 0.3};
  s.obstacles.push_back(wall);
  return s;
}

// Straight drive along +x at 0.2 m/s: 20 mm per 0.1 s period.
Trajectory straightLine(const RobotDef& robot, int periods) {
  Trajectory t;
  const WheelSpeeds w = toWheelSpeeds({0.2, 0.0}, robot);
  Pose2 p{0.0, 0.5, 0.0};
  for (int i = 0; i < periods; ++i) {
    t.points.push_back({0.1 * i, p, w});
    p = integrateExact(p, toTwist(w, robot), 0.1);
  }
  t.points.push_back({0.1 * periods, p, {}});
  return t;
}

TEST(MotionValidator, CatchesAThinObstacleACornerClipsBetweenSamples) {
  const RobotDef robot;
  // Turn in place at 4 rad/s: the rear corners (82 mm out) sweep ~33 mm per period.
  const WheelSpeeds w = toWheelSpeeds({0.0, 4.0}, robot);
  Trajectory t;
  Pose2 p{1.0, 1.0, 0.0};
  for (int i = 0; i < 4; ++i) {
    t.points.push_back({0.1 * i, p, w});
    p = integrateExact(p, toTwist(w, robot), 0.1);
  }
  t.points.push_back({0.4, p, {}});
  const double r = footprintRadius(robot);
  // Find a tiny obstacle on the rear-left corner's circle that no sampled footprint overlaps.
  bool found = false;
  for (int k = 0; k < 400 && !found; ++k) {
    const double phi = kPi + 0.5 + 1.2 * k / 400.0;
    Scenario s;
    Obstacle dot;
    dot.name = "dot";
    dot.box.center = {1.0 + (r - 0.0005) * std::cos(phi), 1.0 + (r - 0.0005) * std::sin(phi)};
    dot.box.half_extents = {0.0004, 0.0004};
    s.obstacles.push_back(dot);
    const SatChecker checker(s);
    bool samples_free = true;
    for (const TrajectoryPoint& q : t.points) samples_free &= checker.isFree(q.pose);
    if (!samples_free) continue;
    found = true;
    const MotionValidator validator(checker, robot, kOpenLot);
    EXPECT_FALSE(validator.isValid(t)) << "phi " << phi;
  }
  EXPECT_TRUE(found) << "test setup: no obstacle hides between samples";
}

TEST(MotionValidator, AcceptsAFreeTrajectoryAndRespectsResolution) {
  const RobotDef robot;
  const Trajectory traj = straightLine(robot, 20);  // x from 0 to 0.4
  // The body ends at x = 0.41 (front edge); a wall 0.6 mm beyond it is clear, even though the
  // validator grows the footprint by half its 1 mm resolution...
  const Scenario far = oneThinWall(0.41 + 0.0006 + 0.0005, 0.001);
  const SatChecker far_checker(far);
  const MotionValidator validator(far_checker, robot, kOpenLot);
  EXPECT_TRUE(validator.isValid(traj));
  // ...while one 0.4 mm beyond it is inside that conservative margin and refused.
  const Scenario near = oneThinWall(0.41 + 0.0004 + 0.0005, 0.001);
  const SatChecker near_checker(near);
  const MotionValidator strict(near_checker, robot, kOpenLot);
  EXPECT_FALSE(strict.isValid(traj));
  EXPECT_GT(validator.queries(), 20 * 20);  // 20 mm per period at 1 mm resolution
}

TEST(SatChecker, AgreesWithCoreGeometryOnRandomPosesAndMargins) {
  // The tests' exact reference checker against core's separating-axis test, obstacle by obstacle.
  Scenario s = testing::studyLot();
  Obstacle tilted;  // a rotated obstacle too
  tilted.box.center = {0.3, 0.9};
  tilted.box.half_extents = {0.1, 0.03};
  tilted.box.yaw = 0.7;
  s.obstacles.push_back(tilted);
  const SatChecker checker(s);
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> x(0.0, 1.8), y(0.0, 1.2), th(-kPi, kPi), m(0.0, 0.002);
  int blocked = 0;
  for (int i = 0; i < 20000; ++i) {
    const Pose2 p{x(rng), y(rng), th(rng)};
    const double margin = i % 2 ? m(rng) : 0.0;
    bool free = true;
    for (const Obstacle& o : s.obstacles)
      free = free && !boxesOverlap(footprintAt(s.robot, p, margin), o.box);
    ASSERT_EQ(checker.isFree(p, margin), free) << "pose " << i;
    blocked += !free;
  }
  EXPECT_GT(blocked, 2000);
}

TEST(MotionValidator, KeepsTheReferencePointInsideTheLot) {
  const RobotDef robot;
  const Trajectory traj = straightLine(robot, 20);  // reference point x from 0 to 0.4, y = 0.5
  const SatChecker free_space((Scenario()));
  EXPECT_TRUE(MotionValidator(free_space, robot, {-0.001, 0.0, 0.401, 1.0}).isValid(traj));
  EXPECT_FALSE(MotionValidator(free_space, robot, {-0.001, 0.0, 0.39, 1.0}).isValid(traj));
  EXPECT_FALSE(MotionValidator(free_space, robot, {-0.001, 0.0, 0.401, 0.4}).isValid(traj));
}

}  // namespace
}  // namespace parksim
