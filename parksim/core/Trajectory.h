#pragma once
// A time-stamped sequence of poses with the wheel speeds that produce them.

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "parksim/core/DiffDrive.h"
#include "parksim/core/Pose2.h"

namespace parksim {

/// One control period. `wheels` are held from t_s until the next point's t_s; integrated
/// exactly (integrateExact) they take `pose` to the next point's pose. The last point of a
/// trajectory carries zero wheel speeds: the robot stops there.
struct TrajectoryPoint {
  double t_s = 0.0;  ///< s since the trajectory's start
  Pose2 pose;
  WheelSpeeds wheels;

  friend bool operator==(const TrajectoryPoint&, const TrajectoryPoint&) = default;
};

struct Trajectory {
  std::vector<TrajectoryPoint> points;

  bool empty() const { return points.empty(); }
  double duration() const { return points.empty() ? 0.0 : points.back().t_s - points.front().t_s; }
  /// Path length travelled by the reference point, m (sum of exact arc lengths).
  double pathLength(const RobotDef& robot) const;
  /// Number of direction reversals of the forward speed (cusps).
  int cusps(const RobotDef& robot) const;
  /// Appends `tail`, whose first pose must equal this trajectory's last pose; tail times are
  /// shifted so they continue this trajectory's clock.
  void append(const Trajectory& tail);

  friend bool operator==(const Trajectory&, const Trajectory&) = default;
};

}  // namespace parksim
