#pragma once
// One episode: a plan driven by the simulated robot (sim/world/DynamicsWorld.h), measured at every
// step against the plan's pose at the same time. The Scenario and the plan are inputs that do
// not change; the Episode is what steps.
//
// Clock: the episode starts at t = 0 with the robot at the plan's first pose, which is plan
// time plan.points.front().t_s. Each step applies the wheel commands computed at its start,
// then measures at its end, so row k of the record is at t = k * dt.

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "parksim/core/geometry/Pose2.h"
#include "parksim/core/model/DiffDrive.h"
#include "parksim/core/model/Scenario.h"
#include "parksim/core/model/Trajectory.h"
#include "parksim/core/system/UserCodeWatch.h"
#include "parksim/sim/control/Controller.h"
#include "parksim/sim/episode/EpisodeMetrics.h"
#include "parksim/sim/episode/ExecutedRow.h"
#include "parksim/sim/episode/ExecutionDef.h"
#include "parksim/sim/world/DynamicsWorld.h"

namespace parksim {

/// What an observer (a renderer, a logger) receives: the row plus the world's moving parts.
/// Plain data, no Bullet types.
struct EpisodeSample {
  ExecutedRow tracking;
  /// Planar pose (box centre, yaw) of every obstacle, in scenario order.
  std::vector<Pose2> obstacles;
  /// Indices of the obstacles the chassis penetrates at this instant, ascending.
  std::vector<int> contacts;
  /// True once the plan's time has run out and the robot is being stopped.
  bool stopping = false;
};

/// Called at a fixed rate of simulated time (see runEpisode).
using EpisodeObserver = std::function<void(const EpisodeSample&)>;

/// The controller an episode's closed-loop tracking asks for commands (Controller.h).
struct EpisodeController {
  /// Null: parksim's tracking controller with its default parameters.
  std::unique_ptr<Controller> controller;
  std::string name = kDefaultController;  ///< its registered name, for metrics and messages
  /// False for a user's controller (ControllerInfo::trusted): its commands are checked (finite,
  /// within the wheel-speed limit) and what it throws or gets wrong ends the episode with a
  /// controller error (EpisodeMetrics::controller_error) instead of propagating.
  bool trusted = true;
  /// Told when an untrusted controller's code starts and ends (UserCodeWatch.h); may be null.
  UserCodeWatch* watch = nullptr;
  /// The run's limit on one command, s (ControllerSetup::time_limit_s; 0: none).
  double time_limit_s = 0.0;
};

/// Physics steps the episode of `plan` may take at most: (plan duration + max_stop_time_s) /
/// the scenario's time step, rounded up. Throws Error, naming the values and the limit, when
/// that exceeds def.max_steps, or when the plan or the time step is unusable; so a tiny
/// time_step_s or a very long plan is refused before the world is built.
double checkEpisodeLimits(const Scenario& scenario, const Trajectory& plan,
                          const ExecutionDef& def = {});

class Episode {
 public:
  /// Builds the world with the robot at the plan's first pose. Copies its inputs. Throws Error
  /// on an empty or non-increasing plan or a bad definition.
  /// `controller` drives closed-loop tracking (reset here, with the plan).
  Episode(const Scenario& scenario, const Trajectory& plan, const ExecutionDef& def = {},
          const SimModelDef& model = {}, EpisodeController controller = {});
  ~Episode();

  Episode(const Episode&) = delete;
  Episode& operator=(const Episode&) = delete;

  /// One simulation step with its measurement, driven by the controller (closed loop) or the
  /// plan's wheel speeds (open loop; ExecutionDef::tracking). Does nothing once finished().
  void step();
  /// One step driven by `command` instead, for a controller outside parksim: the wheel
  /// motors' targets for this step. With a realism control loop (RealismDef) the command
  /// replaces the tracking controller's at the control ticks only and goes the same way
  /// (latency, wheel-speed loop, motors); between ticks it is ignored. The step is measured
  /// against the plan as usual, and the episode still ends at rest after the plan's end or at
  /// the time limit. Does nothing once finished().
  void step(const WheelSpeeds& command);
  /// A car's step driven by `command` (Controller.h's CarCommand), as step(WheelSpeeds) is:
  /// its steering's target and its rear wheels at the commanded speed on the curvature its
  /// steering has. Not checked against the car's limits: the speed is clamped to
  /// max_speed_mps, the steering to max_steer_rad and its rate by the car itself.
  void step(const CarCommand& command);
  /// What the controller commands now, with its input as step() would give it (from its
  /// estimate under a realism). Asks the controller, so a controller with state advances it.
  WheelSpeeds controllerCommand();
  /// At rest after the plan's end, or at the time limit.
  bool finished() const;

  /// The current instant, with obstacle poses.
  EpisodeSample sample() const;
  /// The current row alone (EpisodeSample::tracking), without the obstacle poses and contacts
  /// sample() gathers: what a controller stepping the episode reads every action.
  const ExecutedRow& current() const;
  /// Every recorded row so far (one per csv_stride_steps steps, plus the first and the last).
  const std::vector<ExecutedRow>& rows() const;
  /// Pose measurements the controller received so far, in arrival order.
  const std::vector<PoseMeasurement>& poseSamples() const;
  /// Summary of the steps so far; "final" means the current instant.
  EpisodeMetrics metrics() const;

  const DynamicsWorld& world() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

struct EpisodeResult {
  EpisodeMetrics metrics;
  std::vector<ExecutedRow> rows;
  std::vector<PoseMeasurement> pose_samples;
};

/// Runs an episode to its end. If `observer` is set, it gets the first instant and then the
/// first instant at or after every multiple of observer_period_s (exactly every multiple when
/// the period is a whole number of steps; 1/30 s is 8 steps at 240 Hz), and the last instant.
EpisodeResult runEpisode(const Scenario& scenario, const Trajectory& plan,
                         const ExecutionDef& def = {}, const EpisodeObserver& observer = {},
                         double observer_period_s = 1.0 / 30.0, EpisodeController controller = {});

}  // namespace parksim
