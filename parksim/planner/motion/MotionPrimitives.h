#pragma once
// Hybrid A*'s moves: from a pose, drive a fixed arc length forward or backward on an arc of the
// turning radius (left or right) or straight, or turn in place by a fixed angle (a diff-drive
// robot can). Each move is one PathPiece (TimeOptimalTiming.h), so a chain of moves is exact
// geometry that timing and validation follow without approximation.

#include <vector>

#include "parksim/core/geometry/Pose2.h"
#include "parksim/core/model/RobotDef.h"
#include "parksim/core/model/Trajectory.h"
#include "parksim/planner/motion/TimeOptimalTiming.h"

namespace parksim {

struct MotionPrimitive {
  /// What the robot does in one unit of time: v (m) and omega (rad) held for 1 s.
  Twist motion;
  int direction = 0;      ///< +1 forward, -1 reverse, 0 turning in place
  double length_m = 0.0;  ///< distance the reference point travels
  double turn_rad = 0.0;  ///< heading change magnitude
};

/// Forward and reverse moves of `step_m` straight and on arcs of each of `radii_m` (left and
/// right); with `turn_in_place_rad` > 0 also in-place turns by that angle both ways.
std::vector<MotionPrimitive> makePrimitives(double step_m, const std::vector<double>& radii_m,
                                            double turn_in_place_rad);

/// As above with in-place turns by each of `spin_angles_rad` (each > 0), both ways.
std::vector<MotionPrimitive> makePrimitives(double step_m, const std::vector<double>& radii_m,
                                            const std::vector<double>& spin_angles_rad);

/// Where `m` takes the robot from `from`.
Pose2 applyPrimitive(const Pose2& from, const MotionPrimitive& m);

/// The move as one exact piece.
PathPiece pieceOf(const MotionPrimitive& m, const RobotDef& robot);

/// A geometric trajectory along `pieces` from `start`: one row per piece, 1 s apart, each
/// holding the piece's whole travel (speeds unbounded; for motion validation, which follows the
/// exact arcs at its own resolution whatever the speed).
Trajectory geometryOf(const Pose2& start, const std::vector<PathPiece>& pieces,
                      const RobotDef& robot);

}  // namespace parksim
