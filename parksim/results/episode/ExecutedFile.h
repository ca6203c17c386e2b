#pragma once
// An episode's record: executed.csv (one row per recorded step of an episode) and sensors.csv
// (the pose measurements the controller received), or the same columns as executed.npz and
// sensors.npz (RecordFormat::kNpz: NumPy archives, NpzFile.h), which take a third or less of the
// bytes (docs/simulation.md, "Recorded rows"). Numbers round-trip exactly in both (CSV: 17
// significant digits written with std::to_chars whatever the locale; NPZ: the doubles'
// bytes); files are written atomically.

#include <string>
#include <vector>

#include "parksim/results/episode/NpzFile.h"
#include "parksim/sim/episode/Episode.h"

namespace parksim {

/// How an episode's record is stored.
enum class RecordFormat {
  kCsv,  ///< executed.csv, sensors.csv: text any tool reads
  kNpz,  ///< executed.npz, sensors.npz: numpy.load reads them; a third of the bytes or less
};

const char* toString(RecordFormat format);
/// Parses "csv" or "npz"; throws Error otherwise.
RecordFormat recordFormatFromString(const std::string& name);

/// "executed.csv" or "executed.npz".
std::string executedFileName(RecordFormat format);
/// "sensors.csv" or "sensors.npz".
std::string sensorsFileName(RecordFormat format);

/// executed.csv's text. Header:
/// t,x,y,theta,x_ref,y_ref,theta_ref,omega_left_cmd,omega_right_cmd,omega_left,omega_right,
/// pos_err,heading_err (s, m, rad, rad/s; pos_err in m, heading_err = theta - theta_ref in rad).
/// With `realism_columns` (a realism other than ideal) 13 more follow:
/// x_est,y_est,theta_est,est_pos_err,est_heading_err,effort_left,effort_right,torque_left,
/// torque_right,slip_left,slip_right,encoder_left,encoder_right (m, rad, effort -1..1, N m,
/// m/s, rad). Without them the file is exactly what parksim wrote before realism existed.
/// With `steer_columns` (a car, RobotDef::isCar) 3 more follow last: steer_ref,steer_cmd,steer
/// (the plan's steering angle, the steering's target, the measured angle: bicycle angles in
/// rad, ExecutedRow.h); a differential drive's file is what it was before cars.
std::string executedCsv(const std::vector<ExecutedRow>& rows, bool realism_columns = false,
                        bool steer_columns = false);

/// Writes executedCsv(rows, realism_columns, steer_columns) to `path`. Throws Error.
void writeExecutedCsv(const std::string& path, const std::vector<ExecutedRow>& rows,
                      bool realism_columns = false, bool steer_columns = false);

/// executedCsv's columns as data, in its order and with its names.
std::vector<DataColumn> executedColumns(const std::vector<ExecutedRow>& rows,
                                        bool realism_columns = false, bool steer_columns = false);

/// Writes the rows to `path` in `format` (the name is the caller's: executedFileName). Throws
/// Error.
void writeExecutedFile(const std::string& path, const std::vector<ExecutedRow>& rows,
                       bool realism_columns, RecordFormat format, bool steer_columns = false);

/// sensors.csv's text: the pose measurements the controller received, in arrival order.
/// Header t_received,t_taken,x,y,theta (s, m, rad; lot frame, with the sensor's noise).
std::string sensorsCsv(const std::vector<PoseMeasurement>& samples, double time_step_s);

/// sensorsCsv's columns as data.
std::vector<DataColumn> sensorsColumns(const std::vector<PoseMeasurement>& samples,
                                       double time_step_s);

/// Writes the samples to `path` in `format`. Throws Error.
void writeSensorsFile(const std::string& path, const std::vector<PoseMeasurement>& samples,
                      double time_step_s, RecordFormat format);

/// The columns of a record in either format, chosen by the name (".npz": NPZ, else CSV), in the
/// file's order, the values exactly as written. Throws Error naming the file (and line) on bad
/// input, a CSV longer than kMaxCsvFileBytes or an archive longer than kMaxNpzBytes.
std::vector<DataColumn> readRecordFile(const std::string& path);

/// The column `name` of `columns`; nullptr when there is none.
const DataColumn* findColumn(const std::vector<DataColumn>& columns, const std::string& name);

}  // namespace parksim
