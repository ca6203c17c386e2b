// The parking task with a car (issue 38): actions [acceleration, steering] as highway-env's
// parking-v0 has them, a kinematic bicycle within the car's steering-rate, speed and
// acceleration limits, its speed and steering in the observation, and the reward's order.
// Every expected number is computed here from the car's limits, not by the drive's code.

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "parksim/core/io/Error.h"
#include "parksim/core/model/RobotDef.h"
#include "parksim/rl/ParkingTask.h"
#include "tests/sim/SimTestSupport.h"

namespace parksim {
namespace {

// The mid-size car in an empty 60 m x 60 m lot, facing east from its middle; the goal far away.
Scenario carLot() {
  Scenario s = testing::emptyLot({30.0, 30.0, 0.0});
  s.lot = {0.0, 0.0, 60.0, 60.0};
  s.robot = midSizeCar();
  s.goal.pose = {50.0, 50.0, 0.5 * kPi};
  return s;
}

ParkingTaskDef kinematic() {
  ParkingTaskDef def;
  def.fidelity = TaskFidelity::kKinematic;
  def.max_episode_steps = 0;
  return def;
}

constexpr int kSteps = 24;  // physics steps per 0.1-s action at 240 Hz

TEST(CarTask, SteeringReachesItsTargetAtTheRateLimitWithoutTurningInPlace) {
  const Scenario s = carLot();
  ParkingTask task(s, kinematic());
  const TaskStep& first = task.resetAt(s.start, 0);
  EXPECT_EQ(first.info.steer_rad, 0.0);  // straight wheels at the start
  const double period = task.controlPeriod();
  const RobotDef& car = s.robot;
  for (const double fraction : {0.8, -0.3}) {
    task.resetAt(s.start, 0);
    const double target = fraction * car.max_steer_rad;
    for (int k = 1; k <= 20; ++k) {
      const TaskStep& step = task.step({0.0, fraction});
      const double expected =
          std::copysign(std::min(std::abs(target), car.max_steer_rate_radps * k * period), target);
      EXPECT_NEAR(step.info.steer_rad, expected, 1e-12) << "action " << k;
      EXPECT_NEAR(step.observation[5], expected, 1e-6);
      // Standing still, the car does not move or turn.
      EXPECT_EQ(step.info.pose, s.start);
      EXPECT_EQ(step.info.speed_mps, 0.0);
    }
  }
}

TEST(CarTask, AConstantSteeringAngleDrivesACircleOfRadiusAxleOverTanSteer) {
  const Scenario s = carLot();
  ParkingTask task(s, kinematic());
  task.resetAt(s.start, 0);
  const double fraction = 0.5;
  const double steer = fraction * s.robot.max_steer_rad;
  // Steer while standing until the wheels are at the target (0.375 rad at 0.5 rad/s: 8 actions).
  while (task.step({0.0, fraction}).info.steer_rad != steer) {
    ASSERT_LT(task.steps(), 20);
  }
  const double radius = s.robot.axle_distance_m / std::tan(steer);
  const Pose2& p0 = s.start;  // a left turn: the centre lies left of the heading
  const double cx = p0.x - radius * std::sin(p0.theta);
  const double cy = p0.y + radius * std::cos(p0.theta);
  double turned = 0.0;
  for (int k = 0; k < 200; ++k) {
    const double accel = k < 15 ? 0.6 : 0.0;  // speed up, then hold the speed
    const TaskStep& step = task.step({accel, fraction});
    ASSERT_FALSE(step.terminated);
    const Pose2& p = step.info.pose;
    EXPECT_NEAR(std::hypot(p.x - cx, p.y - cy), radius, 1e-9) << "action " << k;
    // The heading is the circle's tangent: theta = the polar angle + 90 deg.
    EXPECT_NEAR(wrapAngle(p.theta - std::atan2(p.y - cy, p.x - cx) - 0.5 * kPi), 0.0, 1e-9);
    turned = std::max(turned, step.info.speed_mps);
  }
  EXPECT_NEAR(turned, 15 * kSteps * (0.6 * s.robot.max_accel_mps2) / 240.0, 1e-9);
}

TEST(CarTask, AccelerationAndSpeedStayWithinTheCarsLimits) {
  const Scenario s = carLot();
  ParkingTask task(s, kinematic());
  const RobotDef& car = s.robot;
  const double dt = s.physics.time_step_s;
  for (const double sign : {1.0, -1.0}) {
    task.resetAt(s.start, 0);
    double previous = 0.0;
    for (int k = 1; k <= 40; ++k) {
      // Beyond [-1, 1] the action is clipped: full acceleration.
      const TaskStep& step = task.step({3.0 * sign, 0.0});
      const double n = static_cast<double>(k * kSteps);
      const double expected = sign * std::min(car.max_speed_mps, car.max_accel_mps2 * n * dt);
      EXPECT_NEAR(step.info.speed_mps, expected, 1e-12) << "action " << k;
      EXPECT_LE(std::abs(step.info.speed_mps), car.max_speed_mps);
      EXPECT_LE(std::abs(step.info.speed_mps - previous),
                car.max_accel_mps2 * task.controlPeriod() + 1e-12);
      previous = step.info.speed_mps;
      EXPECT_EQ(step.info.pose.y, s.start.y);  // straight wheels: a straight line
      EXPECT_EQ(step.info.pose.theta, s.start.theta);
    }
    // Until the limit, the speed after physics step i is a i dt: the distance is the sum.
    task.resetAt(s.start, 0);
    const TaskStep& step = task.step({sign, 0.0});
    const double n = kSteps;
    const double distance = car.max_accel_mps2 * dt * dt * n * (n + 1.0) / 2.0;
    EXPECT_NEAR(step.info.pose.x - s.start.x, sign * distance, 1e-12);
  }
}

TEST(CarTask, ObservationBoundsAreTheCarsLimits) {
  const Scenario s = carLot();
  const ParkingTask task(s, kinematic());
  const double margin = 2.0 * s.robot.max_speed_mps * task.controlPeriod();
  EXPECT_EQ(task.observationLow()[0], static_cast<float>(-margin));
  EXPECT_EQ(task.observationHigh()[1], static_cast<float>(60.0 + margin));
  EXPECT_EQ(task.observationLow()[4], static_cast<float>(-s.robot.max_speed_mps));
  EXPECT_EQ(task.observationHigh()[4], static_cast<float>(s.robot.max_speed_mps));
  EXPECT_EQ(task.observationLow()[5], static_cast<float>(-s.robot.max_steer_rad));
  EXPECT_EQ(task.observationHigh()[5], static_cast<float>(s.robot.max_steer_rad));
}

TEST(CarTask, ACarStopsAtAWallAndStillSteers) {
  Scenario s = carLot();
  // A wall 0.5 m ahead of the front bumper.
  const double front = s.start.x + s.robot.front_overhang_m;
  testing::addWall(s, "wall", front + 0.5, 20.0, front + 1.0, 40.0);
  s.obstacles.back().height_m = 1.0;  // above the car's ground clearance
  ParkingTaskDef def = kinematic();
  def.terminate_on_contact = false;
  ParkingTask task(s, def);
  task.resetAt(s.start, 0);
  TaskStep step;
  for (int k = 0; k < 20 && step.info.contacts.empty(); ++k) step = task.step({1.0, 0.0});
  ASSERT_EQ(step.info.contacts, std::vector<int>{0});
  EXPECT_EQ(step.info.speed_mps, 0.0);
  EXPECT_LE(step.info.pose.x + s.robot.front_overhang_m, front + 0.5);
  EXPECT_GT(step.info.pose.x + s.robot.front_overhang_m, front + 0.5 - def.kinematic_check_m);
  const double steer = step.info.steer_rad;
  const TaskStep& next = task.step({0.0, 1.0});
  EXPECT_GT(next.info.steer_rad, steer);
}

// The dynamics fidelity: the car in Bullet (sim/CarBody.h), driven by the same actions.
ParkingTaskDef dynamics() {
  ParkingTaskDef def;
  def.fidelity = TaskFidelity::kDynamics;
  def.max_episode_steps = 0;
  return def;
}

// Straight ahead at a constant acceleration action f: the commanded speed ramps at
// f * max_accel_mps2 up to max_speed_mps, and the rear wheels' motors hold the chassis to it. The
// measured speed may lag the command by what one physics step adds to it (a dt) and overshoot
// the limit by as much; the distance is the ramp's integral, off by at most that lag times t.
TEST(CarTask, InDynamicsAConstantAccelerationReachesThePredictedSpeed) {
  const Scenario s = carLot();
  const RobotDef& car = s.robot;
  const double dt = s.physics.time_step_s;
  for (const double fraction : {0.5, -1.0}) {
    ParkingTask task(s, dynamics());
    task.resetAt(s.start, 0);
    const double a = fraction * car.max_accel_mps2;
    const double tolerance = std::abs(a) * dt;
    const double t_limit = car.max_speed_mps / std::abs(a);  // when the ramp reaches the limit
    bool limited = false;
    for (int k = 1; task.steps() * task.controlPeriod() < t_limit + 1.0; ++k) {
      const TaskStep& step = task.step({fraction, 0.0});
      ASSERT_TRUE(step.info.contacts.empty());
      const double t = step.info.t_s;
      const double expected = std::copysign(std::min(car.max_speed_mps, std::abs(a) * t), a);
      EXPECT_NEAR(step.info.speed_mps, expected, tolerance) << "action " << k;
      EXPECT_NEAR(step.observation[4], std::clamp(expected, -car.max_speed_mps, car.max_speed_mps),
                  tolerance);
      const double ramp = std::min(t, t_limit);
      const double distance =
          0.5 * std::abs(a) * ramp * ramp + car.max_speed_mps * std::max(0.0, t - t_limit);
      EXPECT_NEAR(step.info.pose.x - s.start.x, std::copysign(distance, a), tolerance * t);
      // Straight wheels: a straight line (within a millimetre).
      EXPECT_NEAR(step.info.pose.y, s.start.y, 1e-3);
      EXPECT_NEAR(step.info.steer_rad, 0.0, 1e-3);
      limited = limited || t > t_limit;
    }
    EXPECT_TRUE(limited);
  }
}

// The circle through three points: its radius (the circumradius, abc / 4 area).
double circumradius(const Pose2& p, const Pose2& q, const Pose2& r) {
  const double a = std::hypot(q.x - r.x, q.y - r.y);
  const double b = std::hypot(p.x - r.x, p.y - r.y);
  const double c = std::hypot(p.x - q.x, p.y - q.y);
  const double area2 = std::abs((q.x - p.x) * (r.y - p.y) - (q.y - p.y) * (r.x - p.x));
  return a * b * c / (2.0 * area2);
}

// At a constant steering action the servos hold the front wheels at fraction * max_steer_rad,
// and at a walking pace (0.9 m/s: lateral acceleration v^2 / R below 0.12 m/s^2, so the tyres'
// slip is negligible) the rear axle's middle drives a circle of radius
// axle_distance / tan(steer), measured through three of its poses half a turn apart. The 1 %
// tolerance is a steering angle off by about 1 % of itself, or a few millimetres of slip.
TEST(CarTask, InDynamicsAConstantSteeringAngleDrivesACircleOfRadiusAxleOverTanSteer) {
  const Scenario s = carLot();
  const RobotDef& car = s.robot;
  for (const double fraction : {0.5, -0.8}) {
    ParkingTask task(s, dynamics());
    task.resetAt(s.start, 0);
    const double steer = fraction * car.max_steer_rad;
    // Steer while standing: |steer| at max_steer_rate, plus a second to settle.
    const double turn_s = std::abs(steer) / car.max_steer_rate_radps + 1.0;
    while (task.steps() * task.controlPeriod() < turn_s) task.step({0.0, fraction});
    EXPECT_NEAR(task.last().info.steer_rad, steer, 1e-3);
    std::vector<Pose2> poses;
    for (int k = 0; k < 200; ++k) {
      const double accel = k < 15 ? 0.6 : 0.0;  // to 0.9 m/s, then hold the speed
      const TaskStep& step = task.step({accel, fraction});
      ASSERT_TRUE(step.info.contacts.empty());
      if (k >= 30) poses.push_back(step.info.pose);
      if (k >= 30) EXPECT_NEAR(step.info.speed_mps, 0.15 * car.max_accel_mps2 * 6.0, 1e-2);
    }
    const double expected = car.axle_distance_m / std::tan(std::abs(steer));
    const std::size_t n = poses.size();
    const double measured = circumradius(poses.front(), poses[n / 2], poses.back());
    EXPECT_NEAR(measured, expected, 0.01 * expected) << "steer " << steer;
    // Turning the way the wheels point: left for a positive angle.
    EXPECT_GT(wrapAngle(poses[1].theta - poses[0].theta) * steer, 0.0);
  }
}

// The discounted return of an episode driven by `policy` (action k -> action), to its end.
double episodeReturn(const Scenario& s, ParkingTaskDef def,
                     const std::function<TaskAction(long)>& policy, bool* success) {
  def.max_episode_steps = 120;
  ParkingTask task(s, def);
  task.resetAt(s.start, 0);
  double total = 0.0;
  double weight = 1.0;
  for (long k = 0; task.running(); ++k) {
    const TaskStep& step = task.step(policy(k));
    total += weight * step.reward;
    weight *= def.discount;
    *success = step.info.is_success;
  }
  return total;
}

TEST(CarTask, ParkingReturnsMoreThanIdlingOrCrashingWithAndWithoutDiscounting) {
  Scenario s = carLot();
  // The goal straight ahead where 10 actions at full acceleration then 10 at full braking stop:
  // the speeds a i dt up and back down cover a dt^2 n^2 (n = 240 physics steps).
  const double dt = s.physics.time_step_s;
  const double n = 10.0 * kSteps;
  s.goal.pose = {s.start.x + s.robot.max_accel_mps2 * dt * dt * n * n, s.start.y, 0.0};
  // A wall behind the car.
  const double rear = s.start.x - (s.robot.length_m - s.robot.front_overhang_m);
  testing::addWall(s, "wall", rear - 1.0, 20.0, rear - 0.2, 40.0);
  s.obstacles.back().height_m = 1.0;
  for (const double discount : {0.99, 1.0}) {
    ParkingTaskDef def = kinematic();
    def.discount = discount;
    bool parked = false;
    bool crashed = false;
    bool idled = false;
    const double park = episodeReturn(
        s, def,
        [](long k) {
          return TaskAction{k < 10 ? 1.0 : -1.0, 0.0};
        },
        &parked);
    const double crash = episodeReturn(
        s, def,
        [](long) {
          return TaskAction{-1.0, 0.0};
        },
        &crashed);
    const double idle = episodeReturn(
        s, def,
        [](long) {
          return TaskAction{0.0, 0.3};
        },
        &idled);
    EXPECT_TRUE(parked);
    EXPECT_FALSE(crashed || idled);
    EXPECT_LT(crash, 0.0);  // the wall ended it (a time-out's return is not negative)
    EXPECT_GT(park, idle) << "discount " << discount;
    EXPECT_GT(idle, crash) << "discount " << discount;
  }
}

}  // namespace
}  // namespace parksim
