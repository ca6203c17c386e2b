#include "parksim/sim/control/TrackingController.h"

#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "parksim/core/geometry/Angle.h"

namespace parksim {
namespace {

// The study robot's gains for a plan at 0.16 m/s, ticking at 240 Hz.
TrackingGains studyGains(const RobotDef& robot) {
  return trackingGains(TrackingDef{}, robot, 0.16, 1.0 / 240.0, 0.0);
}

TEST(TrackingController, NoErrorGivesTheFeedForward) {
  const RobotDef robot;
  const Pose2 p{0.5, 0.5, 1.0};
  const Twist ff{0.05, 0.3};
  const WheelSpeeds w = trackingCommand(p, p, ff, studyGains(robot), robot);
  const WheelSpeeds expected = toWheelSpeeds(ff, robot);
  EXPECT_NEAR(w.left_radps, expected.left_radps, 1e-12);
  EXPECT_NEAR(w.right_radps, expected.right_radps, 1e-12);
}

TEST(TrackingController, CorrectsTowardsTheReferenceAndRespectsTheWheelLimit) {
  const RobotDef robot;
  const TrackingGains g = studyGains(robot);
  const Pose2 actual{0.0, 0.0, 0.0};
  // Reference ahead: faster. Reference to the left while moving forward: turn left.
  const Twist ahead = toTwist(trackingCommand(actual, {0.001, 0, 0}, {0.05, 0}, g, robot), robot);
  EXPECT_GT(ahead.v_mps, 0.05);
  const Twist left = toTwist(trackingCommand(actual, {0, 0.001, 0}, {0.05, 0}, g, robot), robot);
  EXPECT_GT(left.omega_radps, 0.0);
  // Reversing with the reference to the left: the heading must turn the other way.
  const Twist back = toTwist(trackingCommand(actual, {0, 0.001, 0}, {-0.05, 0}, g, robot), robot);
  EXPECT_LT(back.omega_radps, 0.0);
  const WheelSpeeds big = trackingCommand(actual, {1.0, 0, 0}, {0.19, 0.0}, g, robot);
  EXPECT_LE(std::max(std::abs(big.left_radps), std::abs(big.right_radps)),
            robot.max_wheel_speed_radps + 1e-12);
  const WheelSpeeds scaled = limitWheelSpeeds({20.0, 10.0}, robot);
  EXPECT_EQ(scaled, (WheelSpeeds{10.0, 5.0}));
}

TEST(TrackingController, GainsFollowTheLoopAndThePlansSpeed) {
  const RobotDef robot;
  // 240 Hz, no latency: the bound of 10 rad/s; k_y puts the heading loop's natural frequency
  // at w for the plan's top speed, k_theta damps it at 0.5.
  TrackingGains g = studyGains(robot);
  EXPECT_DOUBLE_EQ(g.k_x, 10.0);
  EXPECT_DOUBLE_EQ(g.k_theta, 10.0);
  EXPECT_NEAR(std::sqrt(g.k_y) * 0.16, 10.0, 1e-12);
  // A 10 Hz loop: 2 pi 10 / 25; a 100 ms latency: 0.25 / 0.1.
  g = trackingGains(TrackingDef{}, robot, 0.16, 0.1, 0.0);
  EXPECT_NEAR(g.k_x, 2.0 * kPi * 10.0 / 25.0, 1e-12);
  g = trackingGains(TrackingDef{}, robot, 0.16, 0.02, 0.1);
  EXPECT_NEAR(g.k_x, 2.5, 1e-12);
  // A plan that barely moves: tuned for 5 % of the robot's top speed (0.2 m/s), not for 0.
  g = trackingGains(TrackingDef{}, robot, 0.0, 1.0 / 240.0, 0.0);
  EXPECT_NEAR(std::sqrt(g.k_y) * 0.01, 10.0, 1e-9);
  // Stated bandwidth and design speed win.
  TrackingDef d;
  d.bandwidth_radps = 3.0;
  d.design_speed_mps = 1.5;
  d.damping = 0.7;
  g = trackingGains(d, robot, 0.16, 1.0 / 240.0, 0.0);
  EXPECT_DOUBLE_EQ(g.k_x, 3.0);
  EXPECT_NEAR(g.k_theta, 4.2, 1e-12);
  EXPECT_NEAR(std::sqrt(g.k_y) * 1.5, 3.0, 1e-12);
}

// A robot of any size, on a straight plan at its design speed from a cross-track offset: the
// linearised loop s^2 + k_theta s + k_y v^2 = s^2 + 2 zeta w s + w^2 predicts an envelope
// decaying as exp(-zeta w t) and an overshoot of exp(-pi zeta / sqrt(1 - zeta^2)) (16.3 % at
// zeta 0.5). The kinematic unicycle under the law follows it, at every scale.
TEST(TrackingController, CrossTrackErrorDecaysAsTheLinearisedLoopPredicts) {
  struct Robot {
    double wheel_base, radius, max_wheel;  // m, m, rad/s
  };
  for (const Robot& r : {Robot{0.085, 0.02, 10.0}, Robot{2.0, 0.3, 10.0}, Robot{0.3, 0.05, 20.0}}) {
    RobotDef robot;
    robot.wheel_base_m = r.wheel_base;
    robot.wheel_radius_m = r.radius;
    robot.max_wheel_speed_radps = r.max_wheel;
    const double v = 0.8 * r.max_wheel * r.radius;  // the plan's top speed
    const double dt = 1.0 / 240.0;
    const TrackingGains g = trackingGains(TrackingDef{}, robot, v, dt, 0.0);
    const double w = g.k_x;
    const double zeta = 0.5;
    // Small against the robot, so the loop stays linear and no wheel saturates.
    const double e0 = 1e-4 * r.wheel_base;
    Pose2 robot_pose{0.0, -e0, 0.0};
    double peak_overshoot = 0.0;
    double at_one_second = 0.0;
    for (int k = 0; k <= 480; ++k) {
      const double t = k * dt;
      const Pose2 ref{v * t, 0.0, 0.0};
      const double cross = robot_pose.y;  // the reference is on y = 0
      if (k == 240) at_one_second = std::abs(cross);
      peak_overshoot = std::max(peak_overshoot, cross);
      const WheelSpeeds cmd = trackingCommand(robot_pose, ref, {v, 0.0}, g, robot);
      robot_pose = integrateExact(robot_pose, toTwist(cmd, robot), dt);
    }
    SCOPED_TRACE("wheel base " + std::to_string(r.wheel_base));
    // Envelope after 1 s: e0 exp(-zeta w) / sqrt(1 - zeta^2) at most (+5 % for sampling).
    const double envelope = e0 * std::exp(-zeta * w * 1.0) / std::sqrt(1.0 - zeta * zeta);
    EXPECT_LE(at_one_second, 1.05 * envelope);
    const double overshoot = e0 * std::exp(-kPi * zeta / std::sqrt(1.0 - zeta * zeta));
    EXPECT_NEAR(peak_overshoot, overshoot, 0.05 * overshoot);
  }
}

}  // namespace
}  // namespace parksim
