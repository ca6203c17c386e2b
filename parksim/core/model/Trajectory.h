#pragma once
// A time-stamped sequence of poses with the wheel speeds that produce them.

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "parksim/core/geometry/Pose2.h"
#include "parksim/core/model/DiffDrive.h"

namespace parksim {

/// A car's row stands still where its speed is at most this fraction of its
/// robot.max_speed_mps (a billionth: the rounding of speeds computed to be zero).
inline constexpr double kCarStillFraction = 1e-9;

/// One control period. `wheels` are held from t_s until the next point's t_s; integrated
/// exactly (integrateExact) they take `pose` to the next point's pose. The last point of a
/// trajectory carries zero wheel speeds: the robot stops there.
///
/// For a car (RobotDef::isCar), `wheels` are its rear wheels' speeds (wheel_base_m is the track,
/// so the same exact integration holds) and steer_rad is the front-wheel angle of the bicycle
/// model, held like the wheels from t_s to the next point: while the car moves, a row's
/// curvature (omega / v) is tan(steer_rad) / axle_distance_m, and consecutive rows' angles
/// differ by at most max_steer_rate_radps times the period. A differential drive's stays 0.
struct TrajectoryPoint {
  double t_s = 0.0;  ///< s since the trajectory's start
  Pose2 pose;
  WheelSpeeds wheels;
  double steer_rad = 0.0;  ///< a car's steering angle from t_s on, rad (left positive)

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
