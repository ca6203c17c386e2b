#include "parksim/core/model/Trajectory.h"

#include <algorithm>
#include <cmath>

namespace parksim {

double Trajectory::pathLength(const RobotDef& robot) const {
  double length = 0.0;
  for (std::size_t i = 0; i + 1 < points.size(); ++i) {
    const double dt = points[i + 1].t_s - points[i].t_s;
    length += std::abs(toTwist(points[i].wheels, robot).v_mps) * dt;
  }
  return length;
}

int Trajectory::cusps(const RobotDef& robot) const {
  int count = 0;
  int last_sign = 0;
  for (std::size_t i = 0; i + 1 < points.size(); ++i) {
    const double v = toTwist(points[i].wheels, robot).v_mps;
    // Speeds below 0.1 mm/s are turning in place, not a direction.
    const int sign = v > 1e-4 ? 1 : (v < -1e-4 ? -1 : 0);
    if (sign != 0) {
      if (last_sign != 0 && sign != last_sign) ++count;
      last_sign = sign;
    }
  }
  return count;
}

void Trajectory::append(const Trajectory& tail) {
  if (tail.points.empty()) return;
  if (points.empty()) {
    points = tail.points;
    return;
  }
  const double t0 = points.back().t_s - tail.points.front().t_s;
  points.pop_back();  // the junction pose is the tail's first point, which carries its wheels
  for (TrajectoryPoint p : tail.points) {
    p.t_s += t0;
    points.push_back(p);
  }
}

}  // namespace parksim
