#pragma once
// The parking task's reward: what an episode's outcome is worth, plus potential-based shaping
// that leads a learner towards the goal without changing which policy is best.
//
// Why this form: a per-step cost makes every early end (a crash, leaving the lot) cheaper than
// a long way to the goal, and did (issue 34). Here the outcome alone ranks the episodes
// (success > 0 = time-out > crash, exit; nothing per step), and the shaping terms telescope:
// with gamma = ParkingTaskDef::discount, the discounted sum of discount * phi(s_{t+1}) -
// phi(s_t) over an episode is gamma^T phi(s_T) - phi(s_0), and phi(s_T) = 0 once the episode
// has terminated. So an episode's return is -phi(s_0) (the same for every episode from that
// start) plus gamma^(T-1) times its outcome, or plus gamma^T phi(s_T) <= 0 for a time-out:
// every successful park beats every crash, exit and time-out, in either fidelity and under
// every realism (the reward judges the true pose).
//
// Why gamma is 1 by default: the return episode statistics log is undiscounted. With gamma <
// 1 a robot standing far from the goal collects (1 - gamma) * D a step of it, without bound
// (issue 39); with gamma 1 it collects nothing, and a learner discounting by its own gamma
// sees an added cost (1 - gamma) * phi(s') <= 0 a step, 0 at the goal: a prompt park wins both.

#include "parksim/core/geometry/Pose2.h"
#include "parksim/core/model/Scenario.h"
#include "parksim/rl/ParkingTaskDef.h"

namespace parksim {

/// The goal distance of highway-env's parking-v0: sqrt(d / distance_scale_m +
/// heading_weight * e / pi), d the distance to the goal position (m), e the heading error
/// (rad). 0 at the goal.
double taskGoalDistance(const ParkingTaskDef& def, double pos_err_m, double heading_err_rad);

/// The shaping potential, -shaping_weight * taskGoalDistance (<= 0).
double taskPotential(const ParkingTaskDef& def, double pos_err_m, double heading_err_rad);

/// How a step ended, as the reward sees it.
struct TaskOutcome {
  bool success = false;     ///< within the success thresholds, no contact during the step
  bool contact = false;     ///< the chassis penetrated an obstacle during the step
  bool exit = false;        ///< the true reference point left the lot
  bool terminated = false;  ///< the episode ended here (success, exit, or a terminating contact)
};

/// How a step that ends at the true pose `pose` ends, towards `goal` in `lot`, with or
/// without a contact during the step: ParkingTask's judgement.
TaskOutcome taskOutcome(const ParkingTaskDef& def, const GoalRegion& goal, const LotBounds& lot,
                        const Pose2& pose, bool contact);

/// The reward of one step from potential `before` to potential `after` (taskPotential).
double taskReward(const ParkingTaskDef& def, double before, double after,
                  const TaskOutcome& outcome);

/// The reward of a step of the true pose from `before` to `after` towards `goal`, in `lot`:
/// ParkingTask's, from the poses alone, so that a goal-conditioned learner can ask it again for
/// another goal (hindsight experience replay, python/parksim/env.py's compute_reward).
double taskTransitionReward(const ParkingTaskDef& def, const GoalRegion& goal, const LotBounds& lot,
                            const Pose2& before, const Pose2& after, bool contact);

}  // namespace parksim
