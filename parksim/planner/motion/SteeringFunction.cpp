#include "parksim/planner/motion/SteeringFunction.h"

#include <cmath>
#include <cstddef>

namespace parksim {

double steeringHorizon(double horizon_s, const RobotDef& robot) {
  return horizon_s == 0.0 ? kStudySteeringHorizon_s * robot.timeScale() : horizon_s;
}

void finishAtTarget(SteerResult& result, const Pose2& to, SteerMode mode, double horizon_s,
                    double period_s) {
  std::vector<TrajectoryPoint>& points = result.trajectory.points;
  const std::size_t full_periods = points.size() - 1;
  const auto horizon_periods = static_cast<std::size_t>(std::lround(horizon_s / period_s));
  if (mode == SteerMode::kFixedHorizon && full_periods > horizon_periods) {
    points.resize(horizon_periods + 1);
    points.back().wheels = {};
    result.reached = false;
    return;
  }
  points.back().pose = to;
  result.reached = true;
}

}  // namespace parksim
