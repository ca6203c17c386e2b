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

/// Writes `t,x,y,theta,omega_left,omega_right,v,omega` (s, m, rad, rad/s, m/s) with
/// round-trip precision. Atomic: the file appears complete or not at all. Throws Error.
void writeTrajectoryCsv(const std::string& path, const Trajectory& traj, const RobotDef& robot);

/// Limits of a plan file (docs/limits.md), checked while reading, before anything is simulated.
struct PlanFileLimits {
  static constexpr std::uintmax_t kMaxBytes = 64u << 20;  ///< file size, bytes
  static constexpr std::size_t kMaxLineBytes = 4096;      ///< one line, bytes
  static constexpr std::size_t kMaxRows = 1'000'000;      ///< data rows
  static constexpr double kMaxTimeS = 3600.0;             ///< every t in [0, kMaxTimeS], s
  static constexpr double kMaxGapS = 60.0;                ///< t step between rows, s
  static constexpr double kMaxMagnitude = 1e6;            ///< |x|, |y| (m), |theta|, wheels
};

/// Reads a file written by writeTrajectoryCsv (extra columns allowed). Only regular files up
/// to PlanFileLimits::kMaxBytes are read. Throws Error naming the file, line and column on bad
/// input, or the limit that was exceeded.
Trajectory readTrajectoryCsv(const std::string& path);

/// As readTrajectoryCsv, from text in memory; `source_name` prefixes messages.
Trajectory parseTrajectoryCsv(std::string_view text, const std::string& source_name);

}  // namespace parksim
