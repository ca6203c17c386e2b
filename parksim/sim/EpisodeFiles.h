#pragma once
// An episode's files: executed.csv (one row per recorded step) and metrics.json (flat keys).
// Both are written atomically; numbers round-trip exactly (shortest round-trip form, written
// with std::to_chars in CSV and by nlohmann in JSON, whatever the locale).

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "parksim/core/Provenance.h"
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

/// metrics.json's content, flat: every value is a number, a boolean or a string, except
/// contact_bodies (a list of names, in the order they were first touched). Parked robots get
/// one key each, parked_displacement_m.<name>. Keys are listed in docs/simulation.md.
nlohmann::json metricsToJson(const EpisodeMetrics& metrics);

/// The metrics a TrackingTolerance checks, read back from metricsToJson's keys. Throws Error
/// naming a missing or mistyped key.
EpisodeMetrics metricsFromJson(const nlohmann::json& json);

/// The provenance as a JSON object (keys of provenanceFields; git_dirty a boolean), the
/// "provenance" entry of plan.json.
nlohmann::json provenanceToJson(const Provenance& provenance);

/// Writes `json` (pretty-printed, two-space indent, trailing newline). Throws Error.
void writeJsonFile(const std::string& path, const nlohmann::json& json);

/// Reads a JSON file. Throws Error naming the file.
nlohmann::json readJsonFile(const std::string& path);

}  // namespace parksim
