#pragma once
// One measured instant of an episode: a row of executed.csv.

#include "parksim/core/geometry/Pose2.h"
#include "parksim/core/model/DiffDrive.h"

namespace parksim {

struct ExecutedRow {
  double t_s = 0.0;              ///< s since the episode's start
  Pose2 pose;                    ///< executed pose of the reference point
  Pose2 reference;               ///< the plan's pose at the same time (exact interpolation)
  WheelSpeeds wheels_cmd;        ///< motor targets applied during the step that ended here
  WheelSpeeds wheels;            ///< measured wheel joint speeds
  double pos_err_m = 0.0;        ///< |position - reference position|, m
  double heading_err_rad = 0.0;  ///< heading - reference heading, wrapped to [-pi, pi), rad
  // A car's steering, bicycle angles (written to executed.csv only for a car):
  double steer_ref_rad = 0.0;  ///< the plan's angle at the same time, rad
  double steer_cmd_rad = 0.0;  ///< the steering's target during the step that ended here, rad
  double steer_rad = 0.0;      ///< measured: the front wheels' joint angles' bicycle angle, rad
  // Realism (written to executed.csv only when the realism is not ideal):
  Pose2 estimate;                    ///< the pose the controller believes (the true pose for truth)
  double est_pos_err_m = 0.0;        ///< |estimate - pose| in position, m
  double est_heading_err_rad = 0.0;  ///< estimate - pose heading, wrapped, rad
  WheelSpeeds effort;                ///< motor effort (PWM duty), -1..1; 0 with ideal motors
  WheelSpeeds torque_nm;             ///< motor drive torque at the wheel, N m; 0 with ideal motors
  WheelSpeeds slip_mps;              ///< rim speed minus contact ground speed per wheel, m/s
  WheelSpeeds encoder_rad;           ///< wheel angles as the encoders report them, rad
};

}  // namespace parksim
