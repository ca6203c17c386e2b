#include "parksim/planner/motion/PathCost.h"

#include <cmath>

namespace parksim {

MotionSummary summarizeMotion(const Trajectory& traj, const RobotDef& robot) {
  MotionSummary m;
  for (std::size_t i = 0; i + 1 < traj.points.size(); ++i) {
    const double dt = traj.points[i + 1].t_s - traj.points[i].t_s;
    const double v = toTwist(traj.points[i].wheels, robot).v_mps;
    m.length_m += std::abs(v) * dt;
    if (v < 0.0) m.reverse_m -= v * dt;
    // Same threshold as Trajectory::cusps: slower is turning in place, not a direction.
    const int dir = v > 1e-4 ? 1 : (v < -1e-4 ? -1 : 0);
    if (dir == 0) continue;
    if (m.first_direction == 0) m.first_direction = dir;
    m.cusps += junctionCusps(m.last_direction, dir);
    m.last_direction = dir;
  }
  return m;
}

double motionCost(const MotionSummary& m, const CostWeights& w) {
  return m.length_m + w.reverse_penalty * m.reverse_m + w.cusp_penalty_m * m.cusps;
}

double trajectoryCost(const Trajectory& traj, const RobotDef& robot, const CostWeights& w) {
  return motionCost(summarizeMotion(traj, robot), w);
}

}  // namespace parksim
