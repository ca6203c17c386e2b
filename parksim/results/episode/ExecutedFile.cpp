#include "parksim/results/episode/ExecutedFile.h"

#include <array>
#include <iterator>

#include "parksim/core/io/AtomicFile.h"
#include "parksim/core/io/Csv.h"
#include "parksim/core/io/Error.h"
#include "parksim/core/io/NumberFormat.h"

namespace parksim {

namespace {

// executed.csv's columns: the 13 every record has, then the 13 of a realism.
constexpr std::array<const char*, 13> kExecutedNames = {"t",
                                                        "x",
                                                        "y",
                                                        "theta",
                                                        "x_ref",
                                                        "y_ref",
                                                        "theta_ref",
                                                        "omega_left_cmd",
                                                        "omega_right_cmd",
                                                        "omega_left",
                                                        "omega_right",
                                                        "pos_err",
                                                        "heading_err"};
constexpr std::array<const char*, 13> kRealismNames = {
    "x_est",       "y_est",        "theta_est",    "est_pos_err",  "est_heading_err",
    "effort_left", "effort_right", "torque_left",  "torque_right", "slip_left",
    "slip_right",  "encoder_left", "encoder_right"};
constexpr std::array<const char*, 3> kSteerNames = {"steer_ref", "steer_cmd", "steer"};
constexpr std::array<const char*, 5> kSensorNames = {"t_received", "t_taken", "x", "y", "theta"};

std::array<double, 13> executedValues(const ExecutedRow& r) {
  return {r.t_s,
          r.pose.x,
          r.pose.y,
          r.pose.theta,
          r.reference.x,
          r.reference.y,
          r.reference.theta,
          r.wheels_cmd.left_radps,
          r.wheels_cmd.right_radps,
          r.wheels.left_radps,
          r.wheels.right_radps,
          r.pos_err_m,
          r.heading_err_rad};
}

std::array<double, 13> realismValues(const ExecutedRow& r) {
  return {r.estimate.x,
          r.estimate.y,
          r.estimate.theta,
          r.est_pos_err_m,
          r.est_heading_err_rad,
          r.effort.left_radps,
          r.effort.right_radps,
          r.torque_nm.left_radps,
          r.torque_nm.right_radps,
          r.slip_mps.left_radps,
          r.slip_mps.right_radps,
          r.encoder_rad.left_radps,
          r.encoder_rad.right_radps};
}

std::array<double, 3> steerValues(const ExecutedRow& r) {
  return {r.steer_ref_rad, r.steer_cmd_rad, r.steer_rad};
}

std::array<double, 5> sensorValues(const PoseMeasurement& m, double time_step_s) {
  return {static_cast<double>(m.arrival_step) * time_step_s,
          static_cast<double>(m.taken_step) * time_step_s, m.pose.x, m.pose.y, m.pose.theta};
}

template <std::size_t N>
void appendCsvLine(std::string& out, const std::array<double, N>& values, bool first) {
  for (std::size_t i = 0; i < N; ++i) {
    if (i > 0 || !first) out += ',';
    appendRoundTrip(out, values[i]);
  }
}

template <std::size_t N>
void appendHeader(std::string& out, const std::array<const char*, N>& names, bool first) {
  for (std::size_t i = 0; i < N; ++i) {
    if (i > 0 || !first) out += ',';
    out += names[i];
  }
}

// Columns named `names` from one value array per row.
template <std::size_t N, typename Rows, typename ValuesOf>
void appendColumns(std::vector<DataColumn>& out, const std::array<const char*, N>& names,
                   const Rows& rows, ValuesOf values_of) {
  const std::size_t first = out.size();
  for (const char* name : names) {
    out.push_back({name, {}});
    out.back().values.reserve(rows.size());
  }
  for (const auto& row : rows) {
    const std::array<double, N> v = values_of(row);
    for (std::size_t i = 0; i < N; ++i) out[first + i].values.push_back(v[i]);
  }
}

std::vector<DataColumn> csvColumns(const std::string& path) {
  const CsvTable csv = readCsvFile(path);
  std::vector<DataColumn> columns;
  for (const std::string& name : csv.header()) columns.push_back({name, {}});
  for (const CsvTable::Row& row : csv.rows()) {
    for (std::size_t c = 0; c < columns.size(); ++c) {
      columns[c].values.push_back(csv.number(row, c));
    }
  }
  return columns;
}

}  // namespace

const char* toString(RecordFormat format) { return format == RecordFormat::kNpz ? "npz" : "csv"; }

RecordFormat recordFormatFromString(const std::string& name) {
  if (name == "csv") return RecordFormat::kCsv;
  if (name == "npz") return RecordFormat::kNpz;
  throw Error("must be npz or csv, got '" + name + "'");
}

std::string executedFileName(RecordFormat format) {
  return std::string("executed.") + toString(format);
}

std::string sensorsFileName(RecordFormat format) {
  return std::string("sensors.") + toString(format);
}

std::string executedCsv(const std::vector<ExecutedRow>& rows, bool realism_columns,
                        bool steer_columns) {
  std::string out;
  appendHeader(out, kExecutedNames, true);
  if (realism_columns) appendHeader(out, kRealismNames, false);
  if (steer_columns) appendHeader(out, kSteerNames, false);
  out += '\n';
  out.reserve(out.size() +
              rows.size() * ((realism_columns ? 600 : 300) + (steer_columns ? 70 : 0)));
  for (const ExecutedRow& r : rows) {
    appendCsvLine(out, executedValues(r), true);
    if (realism_columns) appendCsvLine(out, realismValues(r), false);
    if (steer_columns) appendCsvLine(out, steerValues(r), false);
    out += '\n';
  }
  return out;
}

void writeExecutedCsv(const std::string& path, const std::vector<ExecutedRow>& rows,
                      bool realism_columns, bool steer_columns) {
  writeFileAtomically(path, executedCsv(rows, realism_columns, steer_columns));
}

std::vector<DataColumn> executedColumns(const std::vector<ExecutedRow>& rows, bool realism_columns,
                                        bool steer_columns) {
  std::vector<DataColumn> columns;
  appendColumns(columns, kExecutedNames, rows, executedValues);
  if (realism_columns) appendColumns(columns, kRealismNames, rows, realismValues);
  if (steer_columns) appendColumns(columns, kSteerNames, rows, steerValues);
  return columns;
}

void writeExecutedFile(const std::string& path, const std::vector<ExecutedRow>& rows,
                       bool realism_columns, RecordFormat format, bool steer_columns) {
  if (format == RecordFormat::kNpz) {
    writeNpzFile(path, executedColumns(rows, realism_columns, steer_columns));
  } else {
    writeExecutedCsv(path, rows, realism_columns, steer_columns);
  }
}

std::string sensorsCsv(const std::vector<PoseMeasurement>& samples, double time_step_s) {
  std::string out;
  appendHeader(out, kSensorNames, true);
  out += '\n';
  for (const PoseMeasurement& m : samples) {
    appendCsvLine(out, sensorValues(m, time_step_s), true);
    out += '\n';
  }
  return out;
}

std::vector<DataColumn> sensorsColumns(const std::vector<PoseMeasurement>& samples,
                                       double time_step_s) {
  std::vector<DataColumn> columns;
  appendColumns(columns, kSensorNames, samples,
                [time_step_s](const PoseMeasurement& m) { return sensorValues(m, time_step_s); });
  return columns;
}

void writeSensorsFile(const std::string& path, const std::vector<PoseMeasurement>& samples,
                      double time_step_s, RecordFormat format) {
  if (format == RecordFormat::kNpz) {
    writeNpzFile(path, sensorsColumns(samples, time_step_s));
  } else {
    writeFileAtomically(path, sensorsCsv(samples, time_step_s));
  }
}

std::vector<DataColumn> readRecordFile(const std::string& path) {
  const bool npz = path.size() >= 4 && path.compare(path.size() - 4, 4, ".npz") == 0;
  return npz ? readNpzFile(path) : csvColumns(path);
}

const DataColumn* findColumn(const std::vector<DataColumn>& columns, const std::string& name) {
  for (const DataColumn& c : columns) {
    if (c.name == name) return &c;
  }
  return nullptr;
}

}  // namespace parksim
