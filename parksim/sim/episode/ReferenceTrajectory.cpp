#include "parksim/sim/episode/ReferenceTrajectory.h"

#include <algorithm>
#include <string>

#include "parksim/core/io/Error.h"

namespace parksim {

ReferenceTrajectory::ReferenceTrajectory(const Trajectory& plan, const RobotDef& robot)
    : plan_(plan), robot_(robot) {
  if (plan_.points.empty()) throw Error("simulation: the plan has no points");
  for (std::size_t i = 1; i < plan_.points.size(); ++i) {
    if (!(plan_.points[i].t_s > plan_.points[i - 1].t_s)) {
      throw Error("simulation: plan time does not increase at point " + std::to_string(i));
    }
  }
}

double ReferenceTrajectory::startTime() const { return plan_.points.front().t_s; }
double ReferenceTrajectory::endTime() const { return plan_.points.back().t_s; }

long ReferenceTrajectory::segmentAt(double t_s) const {
  const auto& pts = plan_.points;
  if (t_s < pts.front().t_s) return -1;
  // First point strictly after t_s; the segment is the one before it.
  const auto it = std::upper_bound(pts.begin(), pts.end(), t_s,
                                   [](double t, const TrajectoryPoint& p) { return t < p.t_s; });
  return static_cast<long>(it - pts.begin()) - 1;
}

Pose2 ReferenceTrajectory::poseAt(double t_s) const {
  const long i = segmentAt(t_s);
  if (i < 0) return plan_.points.front().pose;
  const auto last = static_cast<long>(plan_.points.size()) - 1;
  if (i >= last) return plan_.points.back().pose;
  const TrajectoryPoint& p = plan_.points[static_cast<std::size_t>(i)];
  return integrateExact(p.pose, toTwist(p.wheels, robot_), t_s - p.t_s);
}

WheelSpeeds ReferenceTrajectory::wheelsAt(double t_s) const {
  const long i = segmentAt(t_s);
  const auto last = static_cast<long>(plan_.points.size()) - 1;
  if (i < 0 || i >= last) return {};
  return plan_.points[static_cast<std::size_t>(i)].wheels;
}

Twist ReferenceTrajectory::twistAt(double t_s) const { return toTwist(wheelsAt(t_s), robot_); }

double ReferenceTrajectory::steerAt(double t_s) const {
  const long i = segmentAt(t_s);
  return plan_.points[static_cast<std::size_t>(std::max(0L, i))].steer_rad;
}

double ReferenceTrajectory::steerTargetAt(double t_s) const {
  const long i = std::max(0L, segmentAt(t_s));
  const auto& pts = plan_.points;
  const auto next = static_cast<std::size_t>(i) + 1;
  if (next >= pts.size()) return pts.back().steer_rad;
  const double change = std::abs(pts[next].steer_rad - pts[next - 1].steer_rad);
  const double lead =
      robot_.max_steer_rate_radps > 0.0 ? 0.5 * change / robot_.max_steer_rate_radps : 0.0;
  return t_s >= pts[next].t_s - lead ? pts[next].steer_rad : pts[next - 1].steer_rad;
}

}  // namespace parksim
