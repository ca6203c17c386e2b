#include "parksim/core/Trajectory.h"

#include <gtest/gtest.h>

namespace parksim {
namespace {

Trajectory sample() {
  const RobotDef robot;
  Trajectory t;
  Pose2 p{0.1, 0.1, kPi / 2};
  for (int i = 0; i < 10; ++i) {
    const WheelSpeeds w{3.0 + 0.1 * i, 4.0 - 0.2 * i};
    t.points.push_back({0.1 * i, p, w});
    p = integrateExact(p, toTwist(w, robot), 0.1);
  }
  t.points.push_back({1.0, p, {}});
  return t;
}

TEST(Trajectory, AppendJoinsAtTheSharedPose) {
  const RobotDef robot;
  Trajectory a = sample();
  const Trajectory b = sample();
  Trajectory tail = b;
  const Pose2 shift = a.points.back().pose;
  // Make the tail start where a ends by construction: drive it from a's end pose.
  Pose2 p = shift;
  for (auto& pt : tail.points) {
    pt.pose = p;
    p = integrateExact(p, toTwist(pt.wheels, robot), 0.1);
  }
  const std::size_t n = a.points.size();
  a.append(tail);
  EXPECT_EQ(a.points.size(), n + tail.points.size() - 1);
  EXPECT_DOUBLE_EQ(a.duration(), 2.0);
  EXPECT_NEAR(a.pathLength(robot), 2 * b.pathLength(robot), 1e-12);
}

}  // namespace
}  // namespace parksim
