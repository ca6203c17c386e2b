#include "planner/MotionValidator.h"

#include <cmath>

#include "core/Error.h"
#include "core/Geometry.h"

namespace parksim {

MotionValidator::MotionValidator(const FootprintChecker& checker, const RobotDef& robot,
                                 const LotBounds& lot, const MotionValidatorDef& def)
    : checker_(checker), robot_(robot), def_(def) {
  if (!(def.resolution_m > 0.0)) throw Error("motion validator: resolution_m must be positive");
  const double h = 0.5 * def.resolution_m;
  inner_ = {lot.x_min_m + h, lot.y_min_m + h, lot.x_max_m - h, lot.y_max_m - h};
  // Points of the grown footprint lie within this distance of the reference point.
  radius_ = footprintRadius(robot) + std::sqrt(2.0) * 0.5 * def.resolution_m;
}

bool MotionValidator::isValid(const Pose2& pose) const {
  if (!inner_.contains(pose.x, pose.y)) return false;
  ++queries_;
  return checker_.isFree(pose, 0.5 * def_.resolution_m);
}

bool MotionValidator::isValid(const Trajectory& traj) const {
  if (traj.points.empty()) return true;
  for (std::size_t i = 0; i + 1 < traj.points.size(); ++i) {
    const TrajectoryPoint& p = traj.points[i];
    const double dt = traj.points[i + 1].t_s - p.t_s;
    const Twist tw = toTwist(p.wheels, robot_);
    // A footprint point at distance r from the reference point moves at most |v| + |omega| r.
    const double travel = (std::abs(tw.v_mps) + std::abs(tw.omega_radps) * radius_) * dt;
    const int n = std::max(1, static_cast<int>(std::ceil(travel / def_.resolution_m)));
    for (int k = 0; k < n; ++k) {
      const Pose2 q = k == 0 ? p.pose : integrateExact(p.pose, tw, dt * k / n);
      if (!isValid(q)) return false;
    }
  }
  return isValid(traj.points.back().pose);
}

}  // namespace parksim
