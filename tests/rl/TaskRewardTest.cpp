// The parking task's reward (rl/TaskReward.h): the returns of scripted park, crash, exit and
// idle episodes from one start equal what the telescoping shaping predicts, -phi(s_0) plus the
// discounted outcome, and rank the park first for every discount in [0.9, 1]. The Python test
// (tests/python/test_reward.py) does the same in both fidelities and under every realism.

#include "parksim/rl/TaskReward.h"

#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "parksim/core/io/Error.h"
#include "parksim/rl/ParkingTask.h"
#include "tests/sim/SimTestSupport.h"

namespace parksim {
namespace {

// 0.4 m behind the goal, facing it; a wall 30 mm behind the robot's rear edge; the lot's south
// edge 0.3 m to the right.
const Pose2 kStart{0.6, 0.3, 0.0};

Scenario lot() {
  Scenario s = testing::emptyLot(kStart);
  s.goal.pose = {1.0, 0.3, 0.0};
  testing::addWall(s, "wall", 0.45, 0.1, 0.5, 0.5);
  return s;
}

struct Episode {
  double discounted_return = 0.0;
  long steps = 0;
  TaskStep last;
};

// Steps `policy` (step index -> action) until the episode ends; the discounted return.
Episode run(const ParkingTaskDef& def, const std::function<TaskAction(long)>& policy) {
  ParkingTask task(lot(), def);
  task.resetAt(kStart, 0);
  Episode e;
  double weight = 1.0;
  while (task.running()) {
    e.last = task.step(policy(e.steps));
    e.discounted_return += weight * e.last.reward;
    weight *= def.discount;
    ++e.steps;
  }
  return e;
}

double phi(const ParkingTaskDef& def, const Pose2& pose) {
  const Scenario s = lot();
  return -def.shaping_weight *
         std::sqrt(positionDistance(pose, s.goal.pose) / def.distance_scale_m +
                   def.heading_weight * goalHeadingError(s.goal, pose.theta) / kPi);
}

TEST(TaskReward, ParkingBeatsCrashExitAndIdleForEveryDiscount) {
  for (const double gamma : {0.9, 0.95, 0.99, 1.0}) {
    ParkingTaskDef def;
    def.fidelity = TaskFidelity::kKinematic;
    def.discount = gamma;
    def.max_episode_steps = 40;
    const double start_value = -phi(def, kStart);
    const std::string at = "gamma " + std::to_string(gamma);

    // Full speed ahead: 0.2 m/s, 20 mm per action, the goal at the 20th.
    const Episode park = run(def, [](long) { return TaskAction{1.0, 1.0}; });
    ASSERT_TRUE(park.last.terminated && park.last.info.is_success) << at;
    ASSERT_EQ(park.steps, 20) << at;
    // Reversing into the wall.
    const Episode crash = run(def, [](long) { return TaskAction{-1.0, -1.0}; });
    ASSERT_TRUE(crash.last.terminated && !crash.last.info.contacts.empty()) << at;
    // A quarter turn to the right, then out of the lot's south edge.
    const Episode exit = run(def, [](long k) {
      return k < 3 ? TaskAction{1.0, -1.0} : TaskAction{1.0, 1.0};
    });
    ASSERT_TRUE(exit.last.terminated && exit.last.info.pose.y < 0.0) << at;
    ASSERT_TRUE(exit.last.info.contacts.empty()) << at;
    // Standing still until the step limit.
    const Episode idle = run(def, [](long) { return TaskAction{0.0, 0.0}; });
    ASSERT_TRUE(idle.last.truncated && !idle.last.terminated) << at;
    ASSERT_EQ(idle.steps, 40) << at;

    // The shaping telescopes: -phi(s_0) plus the outcome discounted to the last step, or, at a
    // time-out, plus gamma^T phi(s_T).
    const auto outcome = [gamma](const Episode& e, double value) {
      return std::pow(gamma, static_cast<double>(e.steps - 1)) * value;
    };
    EXPECT_NEAR(park.discounted_return, start_value + outcome(park, def.success_reward), 1e-9)
        << at;
    EXPECT_NEAR(crash.discounted_return, start_value + outcome(crash, def.contact_reward), 1e-9)
        << at;
    EXPECT_NEAR(exit.discounted_return, start_value + outcome(exit, def.exit_reward), 1e-9) << at;
    EXPECT_NEAR(idle.discounted_return,
                start_value + std::pow(gamma, 40.0) * phi(def, idle.last.info.pose), 1e-9)
        << at;

    EXPECT_GT(park.discounted_return, idle.discounted_return) << at;
    EXPECT_GT(idle.discounted_return, crash.discounted_return) << at;
    EXPECT_GT(idle.discounted_return, exit.discounted_return) << at;
  }
}

TEST(TaskReward, WithoutShapingTheOutcomeAloneIsTheReward) {
  ParkingTaskDef def;
  def.shaping_weight = 0.0;
  const TaskOutcome none;
  EXPECT_EQ(taskReward(def, taskPotential(def, 0.3, 1.0), taskPotential(def, 0.2, 0.5), none), 0.0);
  TaskOutcome park;
  park.success = park.terminated = true;
  EXPECT_EQ(taskReward(def, 0.0, 0.0, park), def.success_reward);
}

TEST(TaskReward, TheGoalDistanceIsParkingV0s) {
  const ParkingTaskDef def;
  EXPECT_DOUBLE_EQ(taskGoalDistance(def, 0.1, kPi), std::sqrt(1.0 + 0.3));
  EXPECT_EQ(taskGoalDistance(def, 0.0, 0.0), 0.0);
  EXPECT_DOUBLE_EQ(taskPotential(def, 0.1, kPi), -std::sqrt(1.3));
}

TEST(TaskReward, ADefinitionThatWouldBreakTheOrderIsRefused) {
  const auto refused = [](const std::function<void(ParkingTaskDef&)>& change,
                          const std::string& field) {
    ParkingTaskDef def;
    change(def);
    try {
      validateTaskDef(def);
      ADD_FAILURE() << field << " accepted";
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find(field), std::string::npos) << e.what();
    }
  };
  refused([](ParkingTaskDef& d) { d.success_reward = 0.0; }, "success_reward");
  refused([](ParkingTaskDef& d) { d.contact_reward = 1.0; }, "contact_reward");
  refused([](ParkingTaskDef& d) { d.exit_reward = 0.5; }, "exit_reward");
  refused([](ParkingTaskDef& d) { d.discount = 0.0; }, "discount");
  refused([](ParkingTaskDef& d) { d.discount = 1.01; }, "discount");
  refused([](ParkingTaskDef& d) { d.shaping_weight = -1.0; }, "shaping_weight");
}

}  // namespace
}  // namespace parksim
