#include "parksim/realism/Estimator.h"

#include <cmath>

#include <Eigen/LU>

#include "parksim/core/geometry/Angle.h"
#include "parksim/core/io/Error.h"

namespace parksim {

const char* toString(EstimatorKind kind) {
  switch (kind) {
    case EstimatorKind::kTruth: return "truth";
    case EstimatorKind::kOdometry: return "odometry";
    case EstimatorKind::kFused: return "fused";
  }
  return "?";
}

EstimatorKind estimatorKindFromString(const std::string& name) {
  if (name == "truth") return EstimatorKind::kTruth;
  if (name == "odometry") return EstimatorKind::kOdometry;
  if (name == "fused") return EstimatorKind::kFused;
  throw Error("unknown estimator '" + name + "'; expected truth, odometry or fused");
}

Estimator::Estimator(const EstimatorDef& def, const RobotDef& nominal, const PoseSensorDef& sensor,
                     const Pose2& start)
    : def_(def), track_(nominal.wheel_base_m) {
  const double sp =
      def.assumed_position_noise_m > 0.0 ? def.assumed_position_noise_m : sensor.position_noise_m;
  const double sh = def.assumed_heading_noise_rad > 0.0 ? def.assumed_heading_noise_rad
                                                        : sensor.heading_noise_rad;
  r_ = Eigen::Vector3d(sp * sp, sp * sp, sh * sh).asDiagonal();
  Entry first;
  first.step = 0;
  first.x = {start.x, start.y, start.theta};
  first.p = Eigen::Matrix3d::Identity() * 1e-12;
  history_.push_back(first);
}

// Midpoint odometry: exact for arcs up to second order in the step's heading change.
void Estimator::propagate(const Entry& from, Entry& to) const {
  const double ds = 0.5 * (to.left_m + to.right_m);
  const double dth = (to.right_m - to.left_m) / track_;
  const double mid = from.x.z() + 0.5 * dth;
  const double c = std::cos(mid);
  const double s = std::sin(mid);
  to.x = {from.x.x() + ds * c, from.x.y() + ds * s, wrapAngle(from.x.z() + dth)};
  Eigen::Matrix3d f = Eigen::Matrix3d::Identity();
  f(0, 2) = -ds * s;
  f(1, 2) = ds * c;
  // Wheel travels -> pose: d(x, y, theta)/d(left, right).
  Eigen::Matrix<double, 3, 2> g;
  g << 0.5 * c + 0.5 * ds * s / track_, 0.5 * c - 0.5 * ds * s / track_,
      0.5 * s - 0.5 * ds * c / track_, 0.5 * s + 0.5 * ds * c / track_, -1.0 / track_, 1.0 / track_;
  const Eigen::Vector2d q(def_.odometry_variance_per_m * std::abs(to.left_m),
                          def_.odometry_variance_per_m * std::abs(to.right_m));
  to.p = f * from.p * f.transpose() + g * q.asDiagonal() * g.transpose();
}

void Estimator::predict(long step, double left_m, double right_m) {
  Entry next;
  next.step = step;
  next.left_m = left_m;
  next.right_m = right_m;
  propagate(history_.back(), next);
  history_.push_back(next);
  while (static_cast<long>(history_.size()) > def_.history_steps) history_.pop_front();
}

bool Estimator::correct(const PoseMeasurement& m) {
  if (def_.kind != EstimatorKind::kFused) return true;
  const long offset = m.taken_step - history_.front().step;
  if (offset < 0 || offset >= static_cast<long>(history_.size())) return false;
  auto i = static_cast<std::size_t>(offset);
  Entry& e = history_[i];
  Eigen::Vector3d innovation(m.pose.x - e.x.x(), m.pose.y - e.x.y(),
                             angleDiff(m.pose.theta, e.x.z()));
  const Eigen::Matrix3d k = e.p * (e.p + r_).inverse();
  e.x += k * innovation;
  e.x.z() = wrapAngle(e.x.z());
  e.p = (Eigen::Matrix3d::Identity() - k) * e.p;
  for (++i; i < history_.size(); ++i) propagate(history_[i - 1], history_[i]);
  return true;
}

Pose2 Estimator::pose() const {
  const Eigen::Vector3d& x = history_.back().x;
  return {x.x(), x.y(), x.z()};
}

const Eigen::Matrix3d& Estimator::covariance() const { return history_.back().p; }

}  // namespace parksim
