#pragma once
// Time-optimal paths of a differential drive with bounded wheel speeds in free space (Balkcom and
// Mason, "Time optimal trajectories for bounded velocity differential drive vehicles", IJRR
// 21(3), 2002). With each wheel's speed at most V, the time to follow a path is the integral of
// the faster wheel's speed over V, i.e. (|v| + h |omega|) / (r V) with h half the wheel base and
// r the wheel radius: a path costs its length plus h times the angle it turns, and the fastest
// path minimises that. Optimal paths turn in place and drive straight (forward or backward),
// alternately, in at most four actions (every five-action optimum has a four-action equal).
//
// The four-action families are spin-drive-spin-drive and drive-spin-drive-spin (the second is
// the first driven backwards in time from the goal), and they contain the shorter ones. In the
// first, the drive heading psi before the final straight fixes the path; on each stretch where
// the spins keep their senses the cost is smooth in psi, and where it can be stationary cos(psi)
// solves a quadratic. The minimum is the least cost over those stationary points and the
// stretches' ends (spins of zero, a middle drive of zero): a closed form, microseconds per call,
// checked against a brute-force search over five-action paths in tests/planner.

#include <vector>

#include "parksim/core/geometry/Pose2.h"
#include "parksim/core/model/RobotDef.h"
#include "parksim/planner/motion/TimeOptimalTiming.h"

namespace parksim {

/// One action of a spin-and-drive path.
struct SpinDriveAction {
  bool spin = false;    ///< true: turn in place; false: drive straight
  double amount = 0.0;  ///< spin: signed angle, rad (counter-clockwise > 0); drive: signed m
};

struct SpinDrivePath {
  std::vector<SpinDriveAction> actions;  ///< at most four, none of zero amount
  /// Sum of |drive| plus half_base_m times the sum of |spin|, m: the path's time at full wheel
  /// speed V is cost_m / (wheel radius x V).
  double cost_m = 0.0;
};

/// The fastest path from `from` to `to` of a differential drive whose wheels are half_base_m
/// from its reference point (> 0), with bounded wheel speeds and no obstacles.
SpinDrivePath balkcomMasonPath(const Pose2& from, const Pose2& to, double half_base_m);

/// balkcomMasonPath(...).cost_m.
double balkcomMasonCost(const Pose2& from, const Pose2& to, double half_base_m);

/// A lower bound of balkcomMasonCost in O(1): the distance plus half_base_m times the heading
/// change (every path drives at least the one and turns at least the other).
double spinDriveLowerBound(const Pose2& from, const Pose2& to, double half_base_m);

/// Where `path` takes the robot from `from` (exact up to rounding).
Pose2 endPose(const Pose2& from, const SpinDrivePath& path);

/// The path as exact pieces for timing and validation (TimeOptimalTiming.h).
std::vector<PathPiece> piecesOf(const SpinDrivePath& path, const RobotDef& robot);

}  // namespace parksim
