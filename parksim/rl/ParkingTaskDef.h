#pragma once
// The parking task for reinforcement learning: what an agent observes, how its actions move the
// robot, what it is rewarded for and when an episode ends. One definition for the single
// environment (rl/ParkingTask.h) and the batch (rl/TaskBatch.h), and through them for Python's
// ParkingEnv and VecParkingEnv.

#include <cstddef>
#include <string>

#include "parksim/core/Angle.h"
#include "parksim/realism/RealismDef.h"
#include "parksim/sim/DynamicsWorld.h"

namespace parksim {

/// How an action moves the robot.
enum class TaskFidelity {
  /// The Bullet dynamics world (sim/Episode.h), driven by held wheel commands: motors,
  /// contacts and pushed parked robots, and the realism's motors, sensors and estimate.
  kDynamics,
  /// Kinematic, for pre-training: the held wheel speeds move the robot along an exact arc
  /// (core/DiffDrive.h integrateExact), checked against the planner's collision checker
  /// (collision/BulletCollisionWorld.h); no Bullet dynamics, no realism, obstacles never move,
  /// and a robot that would penetrate an obstacle stops at the last free pose of the arc.
  kKinematic,
};

const char* toString(TaskFidelity fidelity);
/// Parses "dynamics" or "kinematic"; throws Error otherwise.
TaskFidelity taskFidelityFromString(const std::string& name);

/// Size of the observation vector: x, y, cos(theta), sin(theta), v, omega of the robot as the
/// controller sees it, then x, y, cos(theta), sin(theta) of the goal.
inline constexpr std::size_t kTaskObservationSize = 10;

struct ParkingTaskDef {
  TaskFidelity fidelity = TaskFidelity::kDynamics;
  /// Each action is held this long, s; rounded to a whole number (at least one) of the world's
  /// physics steps, in both fidelities, so that they share a clock.
  double control_period_s = 0.1;
  /// The episode is truncated after this many actions.
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
  /// Reward per action, as highway-env's parking-v0: -sqrt(d / distance_scale_m +
  /// heading_weight * e / pi), d the distance to the goal position (m), e the heading error
  /// (rad) ...
  double distance_scale_m = 0.1;
  double heading_weight = 0.3;
  /// ... plus this on every action during which the chassis penetrated an obstacle ...
  double contact_reward = -1.0;
  /// ... plus this on success.
  double success_reward = 10.0;
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
