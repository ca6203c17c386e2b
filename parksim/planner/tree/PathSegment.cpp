#include "parksim/planner/tree/PathSegment.h"

#include <algorithm>
#include <cmath>

namespace parksim {

namespace {

// Wheel speed steps this close to the limit are rounding, not violations, rad/s.
constexpr double kStepSlackRadps = 1e-9;

double period(const Trajectory& traj, std::size_t i) {
  return traj.points[i + 1].t_s - traj.points[i].t_s;
}

}  // namespace

WheelSpeeds arrivalWheels(const Trajectory& traj) {
  const std::size_t n = traj.points.size();
  return n >= 2 ? traj.points[n - 2].wheels : WheelSpeeds{};
}

bool withinAccelStep(const WheelSpeeds& a, const WheelSpeeds& b, const RobotDef& robot,
                     double period_s) {
  const double step = robot.max_wheel_accel_radps2 * period_s + kStepSlackRadps;
  return std::abs(a.left_radps - b.left_radps) <= step &&
         std::abs(a.right_radps - b.right_radps) <= step;
}

bool endsWithLegalStop(const Trajectory& traj, const RobotDef& robot) {
  const std::size_t n = traj.points.size();
  return n < 2 || withinAccelStep(traj.points[n - 2].wheels, {}, robot, period(traj, n - 2));
}

Trajectory joinSegments(const std::vector<PathSegment>& segments, const RobotDef& robot) {
  Trajectory out;
  for (const PathSegment& seg : segments) {
    const Trajectory& tail = seg.trajectory;
    if (tail.points.empty()) continue;
    if (out.points.empty() || tail.points.size() < 2) {
      if (out.points.empty()) out = tail;
      continue;  // a one-point segment does not move
    }
    const double dt = period(tail, 0);
    if (out.points.size() < 2 ||
        withinAccelStep(arrivalWheels(out), tail.points.front().wheels, robot, dt)) {
      out.append(tail);
      continue;
    }
    // Stand still for one period at the junction: out's last point carries zero wheel speeds
    // already, so it only needs to last a period before the tail starts.
    const double t0 = out.points.back().t_s + dt;
    for (TrajectoryPoint p : tail.points) {
      p.t_s += t0 - tail.points.front().t_s;
      out.points.push_back(p);
    }
  }
  return out;
}

double segmentsCost(const std::vector<PathSegment>& segments, const RobotDef& robot,
                    const CostWeights& w) {
  double cost = 0.0;
  int last = 0;
  for (const PathSegment& seg : segments) {
    const MotionSummary m = summarizeMotion(seg.trajectory, robot);
    cost += motionCost(m, w) + w.cusp_penalty_m * junctionCusps(last, m.first_direction);
    last = lastDirectionAfter(last, m);
  }
  return cost;
}

}  // namespace parksim
