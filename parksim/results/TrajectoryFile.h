#pragma once
// trajectory.csv: a plan as a file. Written with round-trip precision and read back exactly,
// with the plan-file limits checked while reading (docs/limits.md).

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "parksim/core/RobotDef.h"
#include "parksim/core/Trajectory.h"

namespace parksim {

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
