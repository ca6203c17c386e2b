#include "parksim/sim/episode/EpisodeStatistics.h"

#include <algorithm>
#include <cmath>

#include "parksim/core/geometry/Angle.h"

namespace parksim {

namespace {

// A wheel slips when its rim and its contact point differ by more than this, m/s.
constexpr double kSlipping_mps = 1e-3;

}  // namespace

void EpisodeStatistics::add(const ExecutedRow& row, bool realism) {
  if (realism) {
    max_est_pos_ = std::max(max_est_pos_, row.est_pos_err_m);
    sum_sq_est_pos_ += row.est_pos_err_m * row.est_pos_err_m;
    max_est_heading_ = std::max(max_est_heading_, std::abs(row.est_heading_err_rad));
    max_torque_ = std::max(
        {max_torque_, std::abs(row.torque_nm.left_radps), std::abs(row.torque_nm.right_radps)});
    max_effort_ =
        std::max({max_effort_, std::abs(row.effort.left_radps), std::abs(row.effort.right_radps)});
  }
  for (double slip : {row.slip_mps.left_radps, row.slip_mps.right_radps}) {
    max_slip_ = std::max(max_slip_, std::abs(slip));
    sum_sq_slip_ += slip * slip;
    if (std::abs(slip) > kSlipping_mps) ++slipping_;
  }
  max_pos_ = std::max(max_pos_, row.pos_err_m);
  max_heading_ = std::max(max_heading_, std::abs(row.heading_err_rad));
  sum_sq_pos_ += row.pos_err_m * row.pos_err_m;
  sum_sq_heading_ += row.heading_err_rad * row.heading_err_rad;
  ++count_;
}

void EpisodeStatistics::report(EpisodeMetrics& m) const {
  const auto n = static_cast<double>(count_);
  m.max_pos_err_m = max_pos_;
  m.rms_pos_err_m = std::sqrt(sum_sq_pos_ / n);
  m.max_heading_err_deg = radToDeg(max_heading_);
  m.rms_heading_err_deg = radToDeg(std::sqrt(sum_sq_heading_ / n));
  m.max_est_pos_err_m = max_est_pos_;
  m.rms_est_pos_err_m = std::sqrt(sum_sq_est_pos_ / n);
  m.max_est_heading_err_deg = radToDeg(max_est_heading_);
  m.max_slip_mps = max_slip_;
  m.rms_slip_mps = std::sqrt(sum_sq_slip_ / (2.0 * n));
  m.slip_fraction = static_cast<double>(slipping_) / (2.0 * n);
  m.max_motor_torque_nm = max_torque_;
  m.max_motor_effort = max_effort_;
}

}  // namespace parksim
