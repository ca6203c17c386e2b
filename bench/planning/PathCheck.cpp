#include "bench/planning/PathCheck.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "parksim/core/io/Error.h"
#include "parksim/core/model/DiffDrive.h"
#include "parksim/core/model/Geometry.h"

namespace parksim::bench {

double footprintStep(const Pose2& a, const Pose2& b, double footprint_radius_m) {
  return positionDistance(a, b) + footprint_radius_m * headingDistance(a, b);
}

std::vector<Pose2> densify(const Trajectory& traj, const RobotDef& robot, double max_step_m) {
  if (!(max_step_m > 0.0)) throw Error("densify: max_step_m must be positive");
  std::vector<Pose2> poses;
  const double radius = footprintRadius(robot);
  for (std::size_t i = 0; i + 1 < traj.points.size(); ++i) {
    const TrajectoryPoint& p = traj.points[i];
    const double dt = traj.points[i + 1].t_s - p.t_s;
    const Twist tw = toTwist(p.wheels, robot);
    // Along an arc a point at distance r from the reference point moves at most |v| + |w| r.
    const double travel = (std::abs(tw.v_mps) + std::abs(tw.omega_radps) * radius) * dt;
    const int n = std::max(1, static_cast<int>(std::ceil(travel / max_step_m)));
    for (int k = 0; k < n; ++k) {
      poses.push_back(k == 0 ? p.pose : integrateExact(p.pose, tw, dt * k / n));
    }
  }
  if (!traj.points.empty()) poses.push_back(traj.points.back().pose);
  return poses;
}

PathCheck checkPath(const std::vector<Pose2>& poses, const Scenario& scenario,
                    const BulletCollisionWorld& world, const PathCheckDef& def) {
  PathCheck check;
  check.poses = poses.size();
  check.first_bad = poses.size();
  const double radius = footprintRadius(scenario.robot);
  double min_clearance = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < poses.size(); ++i) {
    const Pose2& q = poses[i];
    if (i > 0) {
      check.length_m += positionDistance(poses[i - 1], q);
      check.max_step_m = std::max(check.max_step_m, footprintStep(poses[i - 1], q, radius));
    }
    const bool free = scenario.lot.contains(q.x, q.y) && world.isFree(q, 0.0);
    if (!free && check.first_bad == poses.size()) check.first_bad = i;
    if (free && def.clearance) min_clearance = std::min(min_clearance, world.clearance(q));
  }
  // Steps are compared with a little slack for the rounding of interpolated poses.
  check.dense_enough = check.max_step_m <= def.max_step_m * (1.0 + 1e-9);
  check.valid = !poses.empty() && check.dense_enough && check.first_bad == poses.size();
  if (!def.clearance) {
    check.min_clearance_m = std::numeric_limits<double>::quiet_NaN();
  } else {
    check.min_clearance_m = check.valid ? min_clearance : 0.0;
  }
  return check;
}

int countCusps(const std::vector<Pose2>& poses) {
  constexpr double kMinReversal = 1e-4;  // m moved the other way before a reversal counts
  int cusps = 0;
  int direction = 0;
  double against = 0.0;  // signed motion since the last step in `direction`
  for (std::size_t i = 1; i < poses.size(); ++i) {
    const Pose2& a = poses[i - 1];
    const Pose2& b = poses[i];
    const double mid = a.theta + 0.5 * angleDiff(b.theta, a.theta);
    const double forward = (b.x - a.x) * std::cos(mid) + (b.y - a.y) * std::sin(mid);
    const int sign = forward > 0.0 ? 1 : (forward < 0.0 ? -1 : 0);
    if (sign == 0) continue;
    if (sign == direction) {
      against = 0.0;
      continue;
    }
    against += forward;
    if (std::abs(against) >= kMinReversal) {
      if (direction != 0) ++cusps;
      direction = sign;
      against = 0.0;
    }
  }
  return cusps;
}

}  // namespace parksim::bench
