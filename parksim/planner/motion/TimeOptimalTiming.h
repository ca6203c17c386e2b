#pragma once
// Time-optimal timing along a fixed geometry. A diff-drive path whose wheel speeds keep one
// ratio over a stretch follows one arc (or straight, or turn in place) there, whatever the
// speed: a path is a list of such pieces, each a wheel-speed direction and how far the faster
// wheel turns along it. Timing chooses the speed along each piece. Rows stay one control period
// apart with constant wheel speeds in between, so every piece takes a whole number of periods
// and the speeds of a period are the piece's direction scaled: the rows integrate exactly to the
// same geometry, only faster or slower.
//
// The profile: each piece's speeds follow the fastest trapezoid that fits it, from the speed it
// enters with to the speed it leaves with; at each junction both neighbouring periods run at
// one speed, the highest at which the wheels change by at most one acceleration step across the
// junction (a cusp: half a step each way; the start and the end: one step from rest). Junction
// speeds start at that limit and are lowered where a piece is too short to go between them.

#include <functional>
#include <vector>

#include "parksim/core/geometry/Pose2.h"
#include "parksim/core/model/DiffDrive.h"
#include "parksim/core/model/RobotDef.h"
#include "parksim/core/model/Trajectory.h"
#include "parksim/planner/motion/SteeringFunction.h"

namespace parksim {

/// One piece of a path: constant wheel-speed direction.
struct PathPiece {
  /// Wheel speeds per unit speed of the faster wheel: max(|left|, |right|) == 1. The sign says
  /// forward or backward.
  WheelSpeeds direction;
  /// Angle the faster wheel turns over the piece, rad (> 0).
  double travel_rad = 0.0;
};

struct TimingLimits {
  double max_wheel_speed_radps = 8.0;    ///< largest wheel speed the timing may use, rad/s
  double max_wheel_accel_radps2 = 40.0;  ///< largest wheel acceleration, rad/s^2
  double period_s = 0.1;                 ///< control period: rows this far apart, s
  /// Jerk limit of the plan's first speed-up from rest, rad/s^3 (0: none). From standstill a
  /// wheel first has to break its drive train's static friction, and the speed loop lags while
  /// it does: a plan that starts at full acceleration runs ahead of the robot. The first piece's
  /// speed then grows by one more J dt^2 each period, up to the acceleration limit.
  double start_jerk_radps3 = 0.0;
};

/// Limits for `robot` leaving `headroom` (in [0, 1)) of its wheel-speed limit to feedback.
TimingLimits timingLimits(const RobotDef& robot, double headroom, double period_s = 0.1,
                          double start_jerk_radps3 = 0.0);

/// The piece `wheels` drive when held for `duration_s`; travel 0 when they stand still.
PathPiece pieceOf(const WheelSpeeds& wheels, double duration_s);

/// Appends `piece` to `pieces`, merged into the last one when their directions agree (to 1e-9).
void appendPiece(std::vector<PathPiece>& pieces, const PathPiece& piece);

/// The trajectory's pieces: consecutive periods with the same wheel-speed direction (to 1e-9)
/// merged, standing-still periods dropped.
std::vector<PathPiece> pathPieces(const Trajectory& traj);

/// The fastest profile along `pieces` from `start` (see the file comment): rows period_s apart
/// from t = 0, from rest to rest, the last row with zero wheel speeds. Each row's wheel speeds
/// integrated exactly give the next row's pose; the speed limit and the acceleration limit
/// (steps of at most max_wheel_accel * period between periods, from and to rest) hold.
Trajectory timePieces(const Pose2& start, const std::vector<PathPiece>& pieces,
                      const RobotDef& robot, const TimingLimits& limits);

/// What a steering function that plans whole paths from rest drives: from `from` it brakes
/// `from_wheels` to rest at the acceleration limit (the last braking row stands still; a car's
/// wheels slow in proportion, so it brakes on its curvature), then
/// follows `pieces_from(pose at rest)` timed by timePieces, the whole on one clock from t = 0.
Trajectory brakeThenTimePieces(
    const Pose2& from, const WheelSpeeds& from_wheels, const RobotDef& robot,
    const TimingLimits& limits,
    const std::function<std::vector<PathPiece>(const Pose2& at_rest)>& pieces_from);

/// steer() of a steering function that plans whole paths from rest (Balkcom-Mason, Reeds-Shepp):
/// brakeThenTimePieces to `to`, then finishAtTarget with `horizon_s` (SteeringFunction.h).
SteerResult steerThroughPieces(
    const Pose2& from, const WheelSpeeds& from_wheels, const Pose2& to, SteerMode mode,
    const RobotDef& robot, const TimingLimits& limits, double horizon_s,
    const std::function<std::vector<PathPiece>(const Pose2& at_rest)>& pieces_from);

/// The duration of timePieces(start, pieces, ...), s, without building its rows: the number of
/// periods the profile takes times the period. O(pieces) per lowering pass.
double timedDuration(const std::vector<PathPiece>& pieces, const TimingLimits& limits);

/// timePieces along the geometry of `traj`, from its first pose. The end pose agrees with the
/// input's up to rounding.
Trajectory retime(const Trajectory& traj, const RobotDef& robot, const TimingLimits& limits);

/// A lower bound on the duration of any timing of `pieces` within `limits`, s: the largest of
/// (a) the faster wheel's total travel from rest to rest and (b) for each wheel, its travel
/// split where it reverses, each part from rest to rest (a wheel passes zero speed there), each
/// driven at the speed and acceleration limits in continuous time. A command held for whole
/// periods can gain at most one period per rest-to-rest part over continuous time, so one
/// period is taken off each part (each part still lasts at least one period).
double durationLowerBound(const std::vector<PathPiece>& pieces, const TimingLimits& limits);

}  // namespace parksim
