#pragma once
// One parking task for reinforcement learning, stepped by actions: reset to a perturbed start,
// hold wheel speeds for a control period, observe, be rewarded, end. The Scenario does not
// change; the task is what steps. Python's ParkingEnv is this class with Gymnasium's interface.
//
// Seeding: episode k after seed(s) draws its start and its realism noise seed from a generator
// seeded by (s, k), so a task's episodes depend on its seed and their number only, never on
// which thread stepped them or what other tasks did.

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "parksim/core/geometry/Pose2.h"
#include "parksim/core/model/Scenario.h"
#include "parksim/rl/ParkingTaskDef.h"
#include "parksim/rl/TaskSpaces.h"

namespace parksim {

/// What the last reset or step produced, besides the observation and reward.
struct TaskInfo {
  Pose2 pose;              ///< the true pose of the reference point
  Pose2 estimate;          ///< the pose the controller believes (the true pose for the ideal robot)
  double t_s = 0.0;        ///< simulated time since the episode's start, s
  double speed_mps = 0.0;  ///< as the controller observes it, negative in reverse
  double steer_rad = 0.0;  ///< a car's front-wheel angle, left positive (0 for a differential)
  double goal_pos_err_m = 0.0;
  double goal_heading_err_rad = 0.0;  ///< either heading when the goal allows it
  /// Within the success thresholds with no contact during the step (then terminated).
  bool is_success = false;
  /// Obstacles (scenario order, ascending) the chassis penetrated during the last action.
  std::vector<int> contacts;
};

struct TaskStep {
  TaskObservation observation{};
  double reward = 0.0;  ///< 0 after a reset (rl/TaskReward.h)
  /// Success, leaving the lot, or a contact (when ParkingTaskDef::terminate_on_contact).
  bool terminated = false;
  /// max_episode_steps actions taken (also when the last one terminated, as Gymnasium's
  /// TimeLimit has it), or kMaxTaskEpisodeSteps.
  bool truncated = false;
  TaskInfo info;
};

/// The state of a task's seeding: the next reset starts episode `episode` of seed `seed`.
struct TaskSeed {
  std::uint64_t seed = 0;
  std::uint64_t episode = 0;
};

class ParkingTask {
 public:
  /// Copies what it needs from `scenario`. Throws Error on a bad definition (validateTaskDef)
  /// or a world the fidelity cannot simulate.
  ParkingTask(const Scenario& scenario, const ParkingTaskDef& def = {});
  ~ParkingTask();
  ParkingTask(ParkingTask&&) noexcept;
  ParkingTask& operator=(ParkingTask&&) noexcept;

  /// The next reset starts episode 0 of `seed`.
  void seed(std::uint64_t seed);
  TaskSeed seedState() const;
  void setSeedState(const TaskSeed& state);

  /// Starts the next episode of the current seed (start and noise seed drawn from it).
  const TaskStep& reset();
  /// Starts an episode at `start` with the realism's noise seed `noise_seed`, drawing nothing
  /// (to replay an episode, or to evaluate from a chosen start). Throws Error when the start is
  /// not finite.
  const TaskStep& resetAt(const Pose2& start, std::uint64_t noise_seed);

  /// Holds `action` for one control period. Throws Error, before anything moves, when an action
  /// value is not finite (checkTaskAction), or when no episode is running (none started, or it
  /// ended).
  const TaskStep& step(const TaskAction& action);

  /// Whether an episode has been started and has not ended (terminated or truncated).
  bool running() const;
  /// Actions taken in the current episode.
  long steps() const;
  /// The result of the last reset or step.
  const TaskStep& last() const;
  /// The current episode's start and noise seed (resetAt with them replays it).
  Pose2 episodeStart() const;
  std::uint64_t episodeNoiseSeed() const;

  /// The control period after rounding to physics steps, s.
  double controlPeriod() const;
  /// Bounds of every observation (taskObservationBounds); observations are clipped into them.
  const TaskObservation& observationLow() const;
  const TaskObservation& observationHigh() const;
  /// Planar pose (box centre, yaw) of every obstacle now, in scenario order.
  std::vector<Pose2> obstaclePoses() const;

  const Scenario& scenario() const;
  const ParkingTaskDef& def() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace parksim
