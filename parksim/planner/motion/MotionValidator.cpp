#include "parksim/planner/motion/MotionValidator.h"

#include <algorithm>
#include <cmath>

#include "parksim/core/io/Error.h"
#include "parksim/core/model/Geometry.h"
#include "parksim/core/model/Scenario.h"

namespace parksim {

MotionValidatorDef resolvedValidation(const MotionValidatorDef& def, const RobotDef& robot) {
  MotionValidatorDef resolved = def;
  if (resolved.resolution_m == 0.0) resolved.resolution_m = motionCheckResolution(robot);
  return resolved;
}

MotionValidator::MotionValidator(const FootprintChecker& checker, const RobotDef& robot,
                                 const LotBounds& lot, const MotionValidatorDef& requested)
    : checker_(checker), robot_(robot), def_(resolvedValidation(requested, robot)) {
  const MotionValidatorDef& def = def_;
  if (!(def.resolution_m > 0.0)) {
    throw Error("motion validator: resolution_m must be positive (or 0: the robot's)");
  }
  // The placement rule's bounds (core's placementProblem), rounding forgiveness included: a goal
  // the world reader accepted 1e-10 m inside the margin was refused here as "within half the
  // motion-check resolution of the lot edge".
  const double h = 0.5 * def.resolution_m - kPlacementTolerance_m;
  inner_ = {lot.x_min_m + h, lot.y_min_m + h, lot.x_max_m - h, lot.y_max_m - h};
  // Points of the grown footprint lie within this distance of the reference point.
  radius_ = footprintRadius(robot) + std::sqrt(2.0) * 0.5 * def.resolution_m;
}

bool MotionValidator::isValid(const Pose2& pose) const {
  if (!inner_.contains(pose.x, pose.y)) return false;
  ++queries_;
  return checker_.isFree(pose, 0.5 * def_.resolution_m);
}

long MotionValidator::prepare(const Trajectory& traj) const {
  const std::vector<TrajectoryPoint>& pts = traj.points;
  // Sample poses along each period's arc so densely that no footprint point moves more than the
  // resolution between two of them; the last pose closes the list.
  periods_.clear();
  long total = 0;
  for (std::size_t i = 0; i + 1 < pts.size(); ++i) {
    const double dt = pts[i + 1].t_s - pts[i].t_s;
    const Twist tw = toTwist(pts[i].wheels, robot_);
    // A footprint point at distance r from the reference point moves at most |v| + |omega| r.
    const double travel = (std::abs(tw.v_mps) + std::abs(tw.omega_radps) * radius_) * dt;
    const int n = std::max(1, static_cast<int>(std::ceil(travel / def_.resolution_m)));
    periods_.push_back({tw, dt, n, total});
    total += n;
  }
  return total + 1;
}

Pose2 MotionValidator::sample(const Trajectory& traj, long idx, std::size_t& period,
                              double* t_s) const {
  const std::vector<TrajectoryPoint>& pts = traj.points;
  const long total = static_cast<long>(traj.points.size()) == 1
                         ? 0
                         : periods_.back().first + periods_.back().samples;
  if (idx == total) {
    if (t_s != nullptr) *t_s = pts.back().t_s;
    return pts.back().pose;
  }
  while (periods_[period].first + periods_[period].samples <= idx) ++period;
  const Period& p = periods_[period];
  const long k = idx - p.first;
  const double dt = p.dt * static_cast<double>(k) / static_cast<double>(p.samples);
  if (t_s != nullptr) *t_s = pts[period].t_s + dt;
  return k == 0 ? pts[period].pose : integrateExact(pts[period].pose, p.twist, dt);
}

bool MotionValidator::isValid(const Trajectory& traj) const {
  if (traj.points.empty()) return true;
  const long count = prepare(traj);
  // Check every kCoarsestStride-th sample first, then halve the stride. These are the same
  // checks as in order, with the same answer, but a footprint that overlaps an obstacle does so
  // over many consecutive samples, so collisions show after few queries.
  for (long stride = kCoarsestStride; stride >= 1; stride /= 2) {
    const bool first_pass = stride == kCoarsestStride;
    std::size_t period = 0;
    for (long idx = first_pass ? 0 : stride; idx < count; idx += first_pass ? stride : 2 * stride) {
      if (!isValid(sample(traj, idx, period))) return false;
    }
  }
  return true;
}

std::optional<MotionValidator::Failure> MotionValidator::firstFailure(
    const Trajectory& traj) const {
  if (traj.points.empty()) return std::nullopt;
  const long count = prepare(traj);
  std::size_t period = 0;
  for (long idx = 0; idx < count; ++idx) {
    double t = 0.0;
    const Pose2 pose = sample(traj, idx, period, &t);
    if (!isValid(pose)) return Failure{t, pose, !insideLot(pose)};
  }
  return std::nullopt;
}

}  // namespace parksim
