#pragma once
// What an episode measured (sim/episode/Episode.h): tracking against the plan, the goal, contacts,
// parked robots, timing, and under a realism the estimate, slip and motors. metrics.json
// (results/MetricsFile.h) writes every field.

#include <cstdint>
#include <string>
#include <vector>

#include "parksim/core/geometry/Pose2.h"
#include "parksim/sim/episode/ExecutionDef.h"

namespace parksim {

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
  /// The controller that drove the plan (closed-loop tracking): its registered name.
  std::string controller = "tracking";  // kDefaultController (Controller.h)
  /// Empty unless the controller (a user's) failed: why, in one line ("controller x returned
  /// nan rad/s at t = 1.250 s"). The episode ended at that tick, its rows and measures up to
  /// there; the verdict is controller_error.
  std::string controller_error;
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

}  // namespace parksim
