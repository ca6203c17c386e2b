#include "parksim/sim/episode/ReferenceTrajectory.h"

#include <gtest/gtest.h>

#include "tests/sim/SimTestSupport.h"

namespace parksim {
namespace {

TEST(ReferenceTrajectory, InterpolatesExactlyAndHoldsTheEnds) {
  const RobotDef robot;
  const Trajectory plan =
      testing::planFromSegments({0.2, 0.3, 0.4}, {{{3.0, 5.0}, 0.3}, {{-2.0, 2.0}, 0.2}}, robot);
  const ReferenceTrajectory ref(plan, robot);
  EXPECT_EQ(ref.poseAt(-1.0), plan.points.front().pose);
  EXPECT_EQ(ref.poseAt(99.0), plan.points.back().pose);
  EXPECT_EQ(ref.wheelsAt(99.0), WheelSpeeds{});
  EXPECT_EQ(ref.wheelsAt(0.25), (WheelSpeeds{3.0, 5.0}));
  EXPECT_EQ(ref.wheelsAt(0.35), (WheelSpeeds{-2.0, 2.0}));
  const Pose2 mid = ref.poseAt(0.137);
  const Pose2 expected = integrateExact(plan.points[1].pose, toTwist({3.0, 5.0}, robot), 0.037);
  EXPECT_EQ(mid, expected);
  EXPECT_EQ(ref.poseAt(plan.points[2].t_s), plan.points[2].pose);
}

}  // namespace
}  // namespace parksim
