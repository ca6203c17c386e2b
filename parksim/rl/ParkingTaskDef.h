#pragma once
// The parking task for reinforcement learning: what an agent observes, how its actions move the
// robot, what it is rewarded for and when an episode ends. One definition for the single
// environment (rl/ParkingTask.h) and the batch (rl/TaskBatch.h), and through them for Python's
// ParkingEnv and VecParkingEnv.

#include <cstddef>
#include <string>

#include "parksim/core/geometry/Angle.h"
#include "parksim/realism/RealismDef.h"
#include "parksim/sim/world/DynamicsWorld.h"

namespace parksim {

/// How an action moves the robot.
enum class TaskFidelity {
  /// The Bullet dynamics world (sim/episode/Episode.h), driven by held wheel commands: motors,
  /// contacts and pushed parked robots, and the realism's motors, sensors and estimate.
  kDynamics,
  /// Kinematic, for pre-training: the held wheel speeds move the robot along an exact arc
  /// (core/model/DiffDrive.h integrateExact), checked against the planner's collision checker
  /// (collision/BulletCollisionWorld.h); no Bullet dynamics, no realism, obstacles never move,
  /// and a robot that would penetrate an obstacle stops at the last free pose of the arc.
  kKinematic,
};

const char* toString(TaskFidelity fidelity);
/// Parses "dynamics" or "kinematic"; throws Error otherwise.
TaskFidelity taskFidelityFromString(const std::string& name);

/// Most actions one episode lasts, whatever max_episode_steps says: an episode nobody ends
/// (max_episode_steps 0 and no caller's time limit) still ends (docs/limits.md).
inline constexpr int kMaxTaskEpisodeSteps = 1'000'000;

struct ParkingTaskDef {
  TaskFidelity fidelity = TaskFidelity::kDynamics;
  /// Each action is held this long, s; rounded to a whole number (at least one) of the world's
  /// physics steps, in both fidelities, so that they share a clock.
  double control_period_s = 0.1;
  /// The episode is truncated after this many actions, as Gymnasium's TimeLimit truncates it:
  /// truncated is true at this step even when the step also terminated. 0: no limit of the
  /// task's own (a caller's time limit governs: gymnasium.make's TimeLimit); at most
  /// kMaxTaskEpisodeSteps either way.
  int max_episode_steps = 300;
  /// reset() perturbs the world's start by up to this much in x and in y, m (uniform) ...
  double start_position_noise_m = 0.02;
  /// ... and in heading, rad (uniform); a perturbed start whose footprint collides is drawn
  /// again (up to 100 times, then the world's start is used).
  double start_heading_noise_rad = 0.2;
  /// Success: the true reference point within this of the goal position, m ...
  double success_position_m = 0.01;
  /// ... and the true heading within this of the goal's (either heading when the goal allows
  /// it), rad. The world's own goal tolerances (1 mm / 0.5 deg in the study) are for plans.
  double success_heading_rad = degToRad(5.0);
  /// The reward (docs/python.md, "Reward"): the task's outcome, success_reward on success,
  /// contact_reward on a step with a contact, exit_reward when the robot leaves the lot, and
  /// nothing per step; plus potential-based shaping, discount * phi(s') - phi(s) with
  /// phi = -shaping_weight * D and phi = 0 once the episode has terminated, D the goal distance
  /// of highway-env's parking-v0: sqrt(d / distance_scale_m + heading_weight * e / pi), d the
  /// distance to the goal position (m), e the heading error (rad). Shaping of this form does
  /// not change which policy is best for a learner discounting by `discount` (Ng, Harada and
  /// Russell 1999): from any start, every successful park returns more than every crash, exit
  /// and time-out, discounted by `discount`.
  double distance_scale_m = 0.1;
  double heading_weight = 0.3;
  /// The shaping's discount, gamma, in (0, 1]. 1 (phi(s') - phi(s)): the undiscounted return,
  /// which episode statistics log, ranks every episode exactly, and a learner discounting by
  /// its own gamma < 1 sees a park promptly made win too (docs/python.md, "Reward"); the
  /// learner's gamma: exactly potential-based for that learner, but a robot standing far from
  /// the goal then collects (1 - gamma) * D a step undiscounted (issue 39).
  double discount = 1.0;
  /// Weight of the shaping potential, >= 0; 0 leaves the outcome's rewards alone (their order
  /// then holds for every discount).
  double shaping_weight = 1.0;
  /// Success: the robot within the success thresholds, with no contact during the step.
  double success_reward = 10.0;
  /// On every action during which the chassis penetrated an obstacle.
  double contact_reward = -10.0;
  /// When the true reference point leaves the lot (the episode terminates).
  double exit_reward = -10.0;
  /// A contact ends the episode (terminated); otherwise the robot may push on.
  bool terminate_on_contact = true;
  /// Motors, sensors and estimate (kDynamics only; kKinematic requires the ideal robot).
  /// The observation is the estimate; reward and termination judge the true pose.
  RealismDef realism;
  /// The dynamics world's model (kDynamics only).
  SimModelDef model;
  /// kKinematic: no point of the footprint moves farther than this between two collision
  /// checks along an arc, m. A penetration between two checks is at most half this deep.
  double kinematic_check_m = 0.002;
};

/// Throws Error naming the first field out of range ("parking task: control_period_s must be
/// positive and finite, got 0").
void validateTaskDef(const ParkingTaskDef& def);

}  // namespace parksim
