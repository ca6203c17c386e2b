#pragma once
// trajectory.csv: a plan as a file. Written with round-trip precision and read back exactly,
// with the plan-file limits checked while reading (docs/limits.md).

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "parksim/core/model/RobotDef.h"
#include "parksim/core/model/Trajectory.h"

namespace parksim {

/// Writes `t,x,y,theta,omega_left,omega_right,v,omega` (s, m, rad, rad/s, m/s), or for a car
/// (RobotDef::isCar, docs/cars.md) `t,x,y,theta,v,steer_rad,curvature,gear` (s, m, rad, m/s of
/// the rear axle's middle, rad of the bicycle model's front wheel, 1/m of tan(steer_rad) /
/// axle_distance, 1 forward, -1 reverse, 0 standing: Trajectory.h's kCarStillFraction), with
/// round-trip precision. Atomic: the file appears complete or not at all. Throws Error, also
/// when the plan exceeds the plan file's limits (planFileProblem: a plan of more than 3600 s in
/// a huge lot), which readTrajectoryCsv would refuse.
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

/// What in `traj` a plan file could not hold (PlanFileLimits), or nothing: writeTrajectoryCsv
/// refuses such a plan, so that every plan file parksim writes `run --plan` reads back.
std::optional<std::string> planFileProblem(const Trajectory& traj);

/// Reads a file written by writeTrajectoryCsv for `robot` (extra columns allowed): a car's
/// from t, x, y, theta, v and steer_rad (|steer_rad| < pi/2; its rear wheels' speeds follow,
/// curvature and gear are not read), a differential drive's from t, x, y, theta, omega_left
/// and omega_right. Only regular files up to PlanFileLimits::kMaxBytes are read. Throws Error
/// naming the file, line and column on bad input, or the limit that was exceeded.
Trajectory readTrajectoryCsv(const std::string& path, const RobotDef& robot = {});

/// As readTrajectoryCsv, from text in memory; `source_name` prefixes messages.
Trajectory parseTrajectoryCsv(std::string_view text, const std::string& source_name,
                              const RobotDef& robot = {});

/// As parseTrajectoryCsv, except that a valid header without rows gives an empty trajectory
/// instead of an error: how a planner that is a command says "no plan" (docs/your-code.md).
Trajectory parseTrajectoryCsvRows(std::string_view text, const std::string& source_name,
                                  const RobotDef& robot = {});

/// Largest file checkTimeSeriesCsv reads: as readCsvFile's (core/io/Csv.h), 32 MiB.
inline constexpr std::uintmax_t kMaxSeriesFileBytes = 32u << 20;

/// Checks another time series in CSV (`render --executed`'s executed.csv) as readTrajectoryCsv
/// checks a plan: a regular file of at most kMaxSeriesFileBytes, lines within kMaxLineBytes, a
/// header naming each column once, every row as wide as the header, at most kMaxRows rows, and
/// in the columns read (`columns`: per column the names it may have, the time first) finite
/// numbers, the time within [0, kMaxTimeS + kMaxGapS] s (a plan and its stop phase),
/// increasing by at most kMaxGapS, the others within
/// +-kMaxMagnitude. Columns not found are not checked (the file's reader names them). Throws
/// Error naming the file, line and column, control bytes escaped.
void checkTimeSeriesCsv(const std::string& path,
                        const std::vector<std::vector<std::string_view>>& columns);

}  // namespace parksim
