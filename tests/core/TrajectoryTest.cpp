#include "parksim/core/model/Trajectory.h"

#include <gtest/gtest.h>

#include "tests/support/SampleTrajectory.h"

namespace parksim {
namespace {

Trajectory sample() { return testing::sampleTrajectory(); }

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
