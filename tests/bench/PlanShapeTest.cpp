#include "bench/planning/PlanShape.h"

#include <gtest/gtest.h>

#include "parksim/core/model/DiffDrive.h"

namespace parksim::bench {
namespace {

// A trajectory of one period per twist, each held 1 s.
Trajectory periods(const std::vector<Twist>& twists, const RobotDef& robot) {
  Trajectory t;
  Pose2 pose;
  for (const Twist& tw : twists) {
    t.points.push_back({static_cast<double>(t.points.size()), pose, toWheelSpeeds(tw, robot)});
    pose = integrateExact(pose, tw, 1.0);
  }
  t.points.push_back({static_cast<double>(t.points.size()), pose, {}});
  return t;
}

TEST(PlanShape, CountsChangesOfTurningDirectionPerMetre) {
  const RobotDef robot;
  // Left, straight, left (one corner), then right, left, right: three reversals in 2 m.
  const Trajectory zigzag =
      periods({{0.4, 0.5}, {0.4, 0.0}, {0.4, 0.3}, {0.2, -0.4}, {0.2, 0.4}, {0.4, -0.2}}, robot);
  const PlanShape s = planShape(zigzag, robot);
  EXPECT_EQ(s.steering_reversals, 3);
  EXPECT_NEAR(s.path_length_m, 2.0, 1e-12);
  EXPECT_NEAR(s.reversals_per_m, 1.5, 1e-12);
  // Slow turning is not turning; a path that does not move has no reversals per metre.
  EXPECT_EQ(planShape(periods({{0.5, 0.01}, {0.5, -0.01}}, robot), robot).steering_reversals, 0);
  EXPECT_EQ(planShape(periods({{0.0, 1.0}, {0.0, -1.0}}, robot), robot).reversals_per_m, 0.0);
}

}  // namespace
}  // namespace parksim::bench
