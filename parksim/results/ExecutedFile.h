#pragma once
// executed.csv (one row per recorded step of an episode) and sensors.csv (the pose measurements
// the controller received). Numbers round-trip exactly (shortest round-trip form, written with
// std::to_chars whatever the locale); files are written atomically.

#include <string>
#include <vector>

#include "parksim/sim/Episode.h"

namespace parksim {

/// executed.csv's text. Header:
/// t,x,y,theta,x_ref,y_ref,theta_ref,omega_left_cmd,omega_right_cmd,omega_left,omega_right,
/// pos_err,heading_err (s, m, rad, rad/s; pos_err in m, heading_err = theta - theta_ref in rad).
/// With `realism_columns` (a realism other than ideal) 13 more follow:
/// x_est,y_est,theta_est,est_pos_err,est_heading_err,effort_left,effort_right,torque_left,
/// torque_right,slip_left,slip_right,encoder_left,encoder_right (m, rad, effort -1..1, N m,
/// m/s, rad). Without them the file is exactly what parksim wrote before realism existed.
std::string executedCsv(const std::vector<ExecutedRow>& rows, bool realism_columns = false);

/// Writes executedCsv(rows, realism_columns) to `path`. Throws Error.
void writeExecutedCsv(const std::string& path, const std::vector<ExecutedRow>& rows,
                      bool realism_columns = false);

/// sensors.csv's text: the pose measurements the controller received, in arrival order.
/// Header t_received,t_taken,x,y,theta (s, m, rad; lot frame, with the sensor's noise).
std::string sensorsCsv(const std::vector<PoseMeasurement>& samples, double time_step_s);

}  // namespace parksim
