// The parking task: exact kinematic arcs, contacts that stop the robot, seeding, the episode's
// end (Gymnasium's TimeLimit semantics), refused actions, observation bounds, and the dynamics
// fidelity's estimate under realism. The reward's own tests: TaskRewardTest.cpp.

#include "parksim/rl/ParkingTask.h"

#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "parksim/collision/BulletCollisionWorld.h"
#include "parksim/core/io/Error.h"
#include "parksim/realism/RealismDef.h"
#include "tests/sim/SimTestSupport.h"
#include "tests/support/StudyLot.h"

namespace parksim {
// Named, not anonymous: its program is compiled as one unity batch, where another file's
// helpers of the same names would meet these.
namespace parking_task_test {

// An empty 2 m x 2 m lot whose goal is far from `start` (emptyLot's goal is its start).
Scenario openLot(const Pose2& start = {0.5, 0.5, 0.0}) {
  Scenario s = testing::emptyLot(start);
  s.goal.pose = {1.5, 1.5, 0.5 * kPi};
  return s;
}

ParkingTaskDef kinematic() {
  ParkingTaskDef def;
  def.fidelity = TaskFidelity::kKinematic;
  return def;
}

TEST(ParkingTask, KinematicStepIsTheExactArcOfTheHeldWheelSpeeds) {
  const Scenario s = openLot({0.5, 0.5, 0.3});
  ParkingTask task(s, kinematic());
  const Pose2 start{0.5, 0.5, 0.3};
  task.resetAt(start, 0);
  const TaskStep& step = task.step({0.5, 0.7});
  const double max = s.robot.max_wheel_speed_radps;
  const Twist twist = toTwist({0.5 * max, 0.7 * max}, s.robot);
  const Pose2 expected = integrateExact(start, twist, task.controlPeriod());
  EXPECT_EQ(step.info.pose, expected);
  EXPECT_EQ(step.info.estimate, expected);
  EXPECT_DOUBLE_EQ(step.info.t_s, task.controlPeriod());
  EXPECT_EQ(step.observation[4], static_cast<float>(twist.v_mps));
  EXPECT_EQ(step.observation[5], static_cast<float>(twist.omega_radps));
  EXPECT_TRUE(step.info.contacts.empty());
  // 0.1 s is 24 physics steps at 240 Hz: both fidelities share the clock.
  EXPECT_DOUBLE_EQ(task.controlPeriod(), 24.0 * s.physics.time_step_s);
}

TEST(ParkingTask, KinematicRobotStopsAtTheLastFreePoseBeforeAnObstacle) {
  Scenario s = openLot({0.5, 0.5, 0.0});
  // A wall 5 mm ahead of the front edge (10 mm ahead of the reference point).
  testing::addWall(s, "wall", 0.515, 0.3, 0.6, 0.7);
  ParkingTaskDef def = kinematic();
  def.terminate_on_contact = false;
  ParkingTask task(s, def);
  task.resetAt({0.5, 0.5, 0.0}, 0);
  const TaskStep step = task.step({1.0, 1.0});
  ASSERT_EQ(step.info.contacts, std::vector<int>{0});
  EXPECT_FALSE(step.terminated);
  EXPECT_FALSE(step.info.is_success);
  // Not terminated: the shaping sees the pose reached, then the contact's penalty.
  const auto phi = [&def, &s](const Pose2& p) {
    return -std::sqrt(positionDistance(p, s.goal.pose) / def.distance_scale_m +
                      def.heading_weight * goalHeadingError(s.goal, p.theta) / kPi);
  };
  EXPECT_DOUBLE_EQ(step.reward,
                   def.discount * phi(step.info.pose) - phi({0.5, 0.5, 0.0}) + def.contact_reward);
  const BulletCollisionWorld collision(s);
  EXPECT_TRUE(collision.isFree(step.info.pose));
  // Stopped within one check of the wall: the front edge at most kinematic_check_m short.
  const double front = step.info.pose.x + s.robot.front_overhang_m;
  EXPECT_LE(front, 0.515);
  EXPECT_GT(front, 0.515 - def.kinematic_check_m);
  EXPECT_EQ(step.observation[4], 0.0F);  // blocked: at rest

  ParkingTask terminating(s, kinematic());
  terminating.resetAt({0.5, 0.5, 0.0}, 0);
  EXPECT_TRUE(terminating.step({1.0, 1.0}).terminated);
}

TEST(ParkingTask, SeedAndEpisodeNumberDecideTheStart) {
  const Scenario s = testing::studyLot();
  ParkingTask a(s, kinematic());
  ParkingTask b(s, kinematic());
  a.seed(7);
  b.seed(7);
  const Pose2 first = a.reset().info.pose;
  EXPECT_EQ(b.reset().info.pose, first);
  const Pose2 second = a.reset().info.pose;
  EXPECT_NE(second, first);
  EXPECT_EQ((a.seedState().seed), 7U);
  EXPECT_EQ((a.seedState().episode), 2U);
  b.setSeedState({7, 1});
  EXPECT_EQ(b.reset().info.pose, second);
  // Within the noise bounds, and collision-free.
  const ParkingTaskDef def;
  EXPECT_LE(std::abs(first.x - s.start.x), def.start_position_noise_m);
  EXPECT_LE(std::abs(angleDiff(first.theta, s.start.theta)), def.start_heading_noise_rad);
  EXPECT_TRUE(BulletCollisionWorld(s).isFree(first));
}

TEST(ParkingTask, RefusesNonFiniteActionsWithoutMoving) {
  const Scenario s = openLot();
  ParkingTask task(s, kinematic());
  EXPECT_THROW(task.step({0.0, 0.0}), Error);  // no episode yet
  task.resetAt({0.5, 0.5, 0.0}, 0);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  for (const TaskAction& bad : {TaskAction{nan, 0.0}, TaskAction{0.0, inf}}) {
    try {
      task.step(bad);
      FAIL() << "accepted a non-finite action";
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find("action: expected two finite numbers"),
                std::string::npos)
          << e.what();
    }
  }
  EXPECT_EQ(task.steps(), 0);
  EXPECT_EQ(task.last().info.pose, (Pose2{0.5, 0.5, 0.0}));
  EXPECT_NO_THROW(task.step({0.2, 0.2}));
}

TEST(ParkingTask, EndsAtTheStepLimitAndRefusesToStepAfterwards) {
  const Scenario s = openLot();
  ParkingTaskDef def = kinematic();
  def.max_episode_steps = 3;
  ParkingTask task(s, def);
  task.resetAt({0.5, 0.5, 0.0}, 0);
  EXPECT_FALSE(task.step({0.1, -0.1}).truncated);
  EXPECT_FALSE(task.step({0.1, -0.1}).truncated);
  const TaskStep last = task.step({0.1, -0.1});
  EXPECT_TRUE(last.truncated);
  EXPECT_FALSE(last.terminated);
  EXPECT_FALSE(task.running());
  EXPECT_THROW(task.step({0.0, 0.0}), Error);
  task.reset();
  EXPECT_TRUE(task.running());
}

TEST(ParkingTask, TheStepLimitTruncatesAStepThatTerminatesAsTimeLimitDoes) {
  // Gymnasium's TimeLimit sets truncated at the limit whatever the step did.
  Scenario s = openLot({0.5, 0.5, 0.0});
  s.goal.pose = s.start;
  ParkingTaskDef def = kinematic();
  def.max_episode_steps = 1;
  ParkingTask task(s, def);
  task.resetAt(s.start, 0);
  const TaskStep step = task.step({0.0, 0.0});
  EXPECT_TRUE(step.terminated && step.info.is_success);
  EXPECT_TRUE(step.truncated);
}

TEST(ParkingTask, WithoutALimitOfItsOwnAnEpisodeRunsPastTheDefault) {
  ParkingTaskDef def = kinematic();
  def.max_episode_steps = 0;  // a caller's time limit governs
  ParkingTask task(openLot(), def);
  task.resetAt({0.5, 0.5, 0.0}, 0);
  for (int i = 0; i < 2 * ParkingTaskDef{}.max_episode_steps; ++i) {
    ASSERT_FALSE(task.step({0.0, 0.0}).truncated) << i;
  }
  EXPECT_TRUE(task.running());
  def.max_episode_steps = kMaxTaskEpisodeSteps + 1;
  EXPECT_THROW(ParkingTask(openLot(), def), Error);
  def.max_episode_steps = -1;
  EXPECT_THROW(ParkingTask(openLot(), def), Error);
}

TEST(ParkingTask, LeavingTheLotTerminatesAndObservationsStayInTheirBounds) {
  const Scenario s = openLot({1.99, 1.0, 0.0});
  ParkingTask task(s, kinematic());
  task.resetAt({1.99, 1.0, 0.0}, 0);
  const TaskStep step = task.step({1.0, 1.0});
  EXPECT_TRUE(step.terminated);
  EXPECT_FALSE(step.truncated);
  // The exit's penalty, and the shaping's last term: phi(terminal) = 0.
  const ParkingTaskDef def;
  const double phi0 =
      -std::sqrt(positionDistance({1.99, 1.0, 0.0}, s.goal.pose) / def.distance_scale_m +
                 def.heading_weight * goalHeadingError(s.goal, 0.0) / kPi);
  EXPECT_DOUBLE_EQ(step.reward, -phi0 + def.exit_reward);
  for (std::size_t i = 0; i < kTaskObservationSize; ++i) {
    EXPECT_GE(step.observation[i], task.observationLow()[i]) << i;
    EXPECT_LE(step.observation[i], task.observationHigh()[i]) << i;
    EXPECT_TRUE(std::isfinite(task.observationLow()[i]) &&
                std::isfinite(task.observationHigh()[i]));
  }
  EXPECT_GT(step.observation[0], 2.0F);  // outside the lot, inside the bounds
}

TEST(ParkingTask, SuccessTerminatesWithTheBonus) {
  Scenario s = openLot({0.5, 0.5, 0.0});
  s.goal.pose = {0.5, 0.5, 0.0};
  ParkingTask task(s, kinematic());
  task.resetAt(s.start, 0);
  const TaskStep step = task.step({0.0, 0.0});
  EXPECT_TRUE(step.info.is_success);
  EXPECT_TRUE(step.terminated);
  EXPECT_DOUBLE_EQ(step.reward, ParkingTaskDef{}.success_reward);
}

TEST(ParkingTask, KinematicFidelityRefusesARealism) {
  ParkingTaskDef def = kinematic();
  def.realism = presetRealism("lab");
  EXPECT_THROW(ParkingTask(openLot(), def), Error);
}

TEST(ParkingTask, DynamicsFollowsTheHeldCommandAndRepeatsBitForBit) {
  const Scenario s = openLot({0.5, 0.5, 0.0});
  ParkingTask a(s);
  ParkingTask b(s);
  a.resetAt(s.start, 0);
  b.resetAt(s.start, 0);
  for (int i = 0; i < 10; ++i) {
    const TaskStep& x = a.step({0.8, 0.8});
    const TaskStep& y = b.step({0.8, 0.8});
    ASSERT_EQ(x.observation, y.observation);
    ASSERT_EQ(x.info.pose, y.info.pose);
  }
  // 1 s forward at 0.16 m/s (after the motors' spin-up): about 0.16 m, straight.
  const Pose2 p = a.last().info.pose;
  EXPECT_NEAR(p.x - 0.5, 0.16, 0.01);
  EXPECT_NEAR(p.y, 0.5, 1e-4);
  EXPECT_EQ(a.last().info.estimate, p);  // the ideal robot's controller knows the truth
  EXPECT_NEAR(a.last().observation[4], 0.16F, 1e-3F);
}

TEST(ParkingTask, UnderARealismTheObservationIsTheEstimate) {
  const Scenario s = openLot({0.5, 0.5, 0.0});
  ParkingTaskDef def;
  def.realism = presetRealism("lab");
  ParkingTask task(s, def);
  task.resetAt(s.start, 3);
  double largest = 0.0;
  for (int i = 0; i < 10; ++i) {
    const TaskStep& step = task.step({0.6, 0.4});
    EXPECT_EQ(step.observation[0], static_cast<float>(step.info.estimate.x));
    EXPECT_EQ(step.observation[1], static_cast<float>(step.info.estimate.y));
    largest = std::max(largest, positionDistance(step.info.estimate, step.info.pose));
  }
  EXPECT_GT(largest, 0.0);    // an estimate, not the truth ...
  EXPECT_LT(largest, 0.005);  // ... of a motion-capture table
  // The noise seed is the realism's: another draws another robot.
  ParkingTask other(s, def);
  other.resetAt(s.start, 4);
  for (int i = 0; i < 10; ++i) other.step({0.6, 0.4});
  EXPECT_NE(other.last().info.pose, task.last().info.pose);
}

}  // namespace parking_task_test
}  // namespace parksim
