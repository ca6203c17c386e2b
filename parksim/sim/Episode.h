#pragma once
// One episode: a plan driven by the simulated robot (sim/DynamicsWorld.h), measured at every
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

#include "parksim/core/DiffDrive.h"
#include "parksim/core/Pose2.h"
#include "parksim/core/Scenario.h"
#include "parksim/core/Trajectory.h"
#include "parksim/sim/DynamicsWorld.h"
#include "parksim/sim/ExecutionDef.h"

namespace parksim {

/// One measured instant: a row of executed.csv.
struct ExecutedRow {
  double t_s = 0.0;              ///< s since the episode's start
  Pose2 pose;                    ///< executed pose of the reference point
  Pose2 reference;               ///< the plan's pose at the same time (exact interpolation)
  WheelSpeeds wheels_cmd;        ///< motor targets applied during the step that ended here
  WheelSpeeds wheels;            ///< measured wheel joint speeds
  double pos_err_m = 0.0;        ///< |position - reference position|, m
  double heading_err_rad = 0.0;  ///< heading - reference heading, wrapped to [-pi, pi), rad
  // Realism (written to executed.csv only when the realism is not ideal):
  Pose2 estimate;                    ///< the pose the controller believes (the true pose for truth)
  double est_pos_err_m = 0.0;        ///< |estimate - pose| in position, m
  double est_heading_err_rad = 0.0;  ///< estimate - pose heading, wrapped, rad
  WheelSpeeds effort;                ///< motor effort (PWM duty), -1..1; 0 with ideal motors
  WheelSpeeds torque_nm;             ///< motor drive torque at the wheel, N m; 0 with ideal motors
  WheelSpeeds slip_mps;              ///< rim speed minus contact ground speed per wheel, m/s
  WheelSpeeds encoder_rad;           ///< wheel angles as the encoders report them, rad
};

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

/// The chassis starting to penetrate an obstacle it had not penetrated for at least
/// ExecutionDef::contact_merge_s.
struct ContactEvent {
  double t_s = 0.0;
  int obstacle_index = -1;  ///< scenario order
  std::string body;         ///< the obstacle's name
};

struct ParkedRobotDisplacement {
  std::string name;
  double max_m = 0.0;    ///< largest horizontal displacement of its centre during the episode, m
  double final_m = 0.0;  ///< at the end, m
};

struct EpisodeMetrics {
  TrackingMode tracking = TrackingMode::kClosed;
  /// Tracking error against the plan's pose at the same time, over every step.
  double max_pos_err_m = 0.0;
  double rms_pos_err_m = 0.0;
  double final_pos_err_m = 0.0;
  double max_heading_err_deg = 0.0;
  double rms_heading_err_deg = 0.0;
  double final_heading_err_deg = 0.0;
  /// Final pose against the scenario's goal (either heading when the goal allows it).
  Pose2 final_pose;
  double goal_pos_err_m = 0.0;
  double goal_heading_err_deg = 0.0;
  /// Within the scenario's goal tolerances at the end.
  bool goal_reached = false;
  /// Contact events between the chassis and anything but the ground.
  int contacts = 0;
  double first_contact_t_s = -1.0;  ///< -1 when there was none
  std::string first_contact_body;   ///< empty when there was none
  std::vector<ContactEvent> contact_events;
  std::vector<ParkedRobotDisplacement> parked;  ///< every parked robot, scenario order
  double max_parked_displacement_m = 0.0;
  double plan_duration_s = 0.0;
  double sim_time_s = 0.0;
  long steps = 0;
  double time_step_s = 0.0;
  /// True when the episode ended because the robot came to rest, false at the time limit.
  bool ended_at_rest = false;
  /// Wall time spent stepping and measuring (observer calls excluded), s.
  double wall_time_s = 0.0;

  // Realism (realism/RealismDef.h).
  std::string realism = "ideal";
  std::uint64_t noise_seed = 0;
  std::string estimator = "truth";
  /// Error of the controller's estimate against the true pose, over every step.
  double max_est_pos_err_m = 0.0;
  double rms_est_pos_err_m = 0.0;
  double max_est_heading_err_deg = 0.0;
  double final_est_pos_err_m = 0.0;
  /// Wheel slip (rim speed minus contact ground speed), both wheels, every step, m/s.
  double max_slip_mps = 0.0;
  double rms_slip_mps = 0.0;
  /// Share of wheel-steps slipping by more than 1 mm/s.
  double slip_fraction = 0.0;
  double max_motor_torque_nm = 0.0;
  double max_motor_effort = 0.0;
  /// The robot as built this episode (drawn calibration and motor gains).
  double true_left_radius_m = 0.0;
  double true_right_radius_m = 0.0;
  double true_track_m = 0.0;
  double left_motor_gain = 1.0;
  double right_motor_gain = 1.0;
  long pose_samples_taken = 0;
  long pose_samples_dropped = 0;
  long pose_samples_received = 0;
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
  Episode(const Scenario& scenario, const Trajectory& plan, const ExecutionDef& def = {},
          const SimModelDef& model = {});
  ~Episode();

  Episode(const Episode&) = delete;
  Episode& operator=(const Episode&) = delete;

  /// One simulation step with its measurement, driven by the tracking controller
  /// (ExecutionDef::tracking). Does nothing once finished().
  void step();
  /// One step driven by `command` instead, for a controller outside parksim: the wheel
  /// motors' targets for this step. With a realism control loop (RealismDef) the command
  /// replaces the tracking controller's at the control ticks only and goes the same way
  /// (latency, wheel-speed loop, motors); between ticks it is ignored. The step is measured
  /// against the plan as usual, and the episode still ends at rest after the plan's end or at
  /// the time limit. Does nothing once finished().
  void step(const WheelSpeeds& command);
  /// What the tracking controller would command now (from its estimate under a realism).
  WheelSpeeds controllerCommand() const;
  /// At rest after the plan's end, or at the time limit.
  bool finished() const;

  /// The current instant, with obstacle poses.
  EpisodeSample sample() const;
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
                         double observer_period_s = 1.0 / 30.0);

}  // namespace parksim
