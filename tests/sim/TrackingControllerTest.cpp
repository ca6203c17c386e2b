#include "parksim/sim/TrackingController.h"

#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

namespace parksim {
namespace {

TEST(TrackingController, NoErrorGivesTheFeedForward) {
  const RobotDef robot;
  const Pose2 p{0.5, 0.5, 1.0};
  const Twist ff{0.05, 0.3};
  const WheelSpeeds w = trackingCommand(p, p, ff, TrackingGains{}, robot);
  const WheelSpeeds expected = toWheelSpeeds(ff, robot);
  EXPECT_NEAR(w.left_radps, expected.left_radps, 1e-12);
  EXPECT_NEAR(w.right_radps, expected.right_radps, 1e-12);
}

TEST(TrackingController, CorrectsTowardsTheReferenceAndRespectsTheWheelLimit) {
  const RobotDef robot;
  const Pose2 actual{0.0, 0.0, 0.0};
  // Reference ahead: faster. Reference to the left while moving forward: turn left.
  const Twist ahead = toTwist(trackingCommand(actual, {0.001, 0, 0}, {0.05, 0}, {}, robot), robot);
  EXPECT_GT(ahead.v_mps, 0.05);
  const Twist left = toTwist(trackingCommand(actual, {0, 0.001, 0}, {0.05, 0}, {}, robot), robot);
  EXPECT_GT(left.omega_radps, 0.0);
  // Reversing with the reference to the left: the heading must turn the other way.
  const Twist back = toTwist(trackingCommand(actual, {0, 0.001, 0}, {-0.05, 0}, {}, robot), robot);
  EXPECT_LT(back.omega_radps, 0.0);
  const WheelSpeeds big = trackingCommand(actual, {1.0, 0, 0}, {0.19, 0.0}, {}, robot);
  EXPECT_LE(std::max(std::abs(big.left_radps), std::abs(big.right_radps)),
            robot.max_wheel_speed_radps + 1e-12);
  const WheelSpeeds scaled = limitWheelSpeeds({20.0, 10.0}, robot);
  EXPECT_EQ(scaled, (WheelSpeeds{10.0, 5.0}));
}

}  // namespace
}  // namespace parksim
