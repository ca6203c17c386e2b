#include "bench/planning/PlanShape.h"

#include <cmath>

#include "parksim/core/model/DiffDrive.h"

namespace parksim::bench {

PlanShape planShape(const Trajectory& plan, const RobotDef& robot, double min_turn_radps) {
  PlanShape s;
  int last = 0;
  for (std::size_t i = 0; i + 1 < plan.points.size(); ++i) {
    const double omega = toTwist(plan.points[i].wheels, robot).omega_radps;
    if (std::abs(omega) < min_turn_radps) continue;
    const int sign = omega > 0.0 ? 1 : -1;
    if (last != 0 && sign != last) ++s.steering_reversals;
    last = sign;
  }
  s.path_length_m = plan.pathLength(robot);
  s.reversals_per_m = s.path_length_m > 0.0 ? s.steering_reversals / s.path_length_m : 0.0;
  return s;
}

}  // namespace parksim::bench
