#include "parksim/results/ExecutedFile.h"

#include <iterator>

#include "parksim/core/AtomicFile.h"
#include "parksim/core/NumberFormat.h"

namespace parksim {

std::string executedCsv(const std::vector<ExecutedRow>& rows, bool realism_columns) {
  std::string out =
      "t,x,y,theta,x_ref,y_ref,theta_ref,omega_left_cmd,omega_right_cmd,omega_left,omega_right,"
      "pos_err,heading_err";
  out += realism_columns ? ",x_est,y_est,theta_est,est_pos_err,est_heading_err,effort_left,"
                           "effort_right,torque_left,torque_right,slip_left,slip_right,"
                           "encoder_left,encoder_right\n"
                         : "\n";
  out.reserve(out.size() + rows.size() * (realism_columns ? 600 : 300));
  for (const ExecutedRow& r : rows) {
    const double values[] = {r.t_s,
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
    for (std::size_t i = 0; i < std::size(values); ++i) {
      if (i > 0) out += ',';
      appendRoundTrip(out, values[i]);
    }
    if (realism_columns) {
      const double extra[] = {r.estimate.x,
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
      for (const double v : extra) {
        out += ',';
        appendRoundTrip(out, v);
      }
    }
    out += '\n';
  }
  return out;
}

void writeExecutedCsv(const std::string& path, const std::vector<ExecutedRow>& rows,
                      bool realism_columns) {
  writeFileAtomically(path, executedCsv(rows, realism_columns));
}

std::string sensorsCsv(const std::vector<PoseMeasurement>& samples, double time_step_s) {
  std::string out = "t_received,t_taken,x,y,theta\n";
  for (const PoseMeasurement& m : samples) {
    const double values[] = {static_cast<double>(m.arrival_step) * time_step_s,
                             static_cast<double>(m.taken_step) * time_step_s, m.pose.x, m.pose.y,
                             m.pose.theta};
    for (std::size_t i = 0; i < std::size(values); ++i) {
      if (i > 0) out += ',';
      appendRoundTrip(out, values[i]);
    }
    out += '\n';
  }
  return out;
}

}  // namespace parksim
