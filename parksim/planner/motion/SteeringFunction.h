#pragma once
// Steering: a trajectory from one pose toward another, with the wheel speeds that drive it.
// The planner sees only this interface, so steering functions are interchangeable per run.

#include "parksim/core/geometry/Pose2.h"
#include "parksim/core/model/DiffDrive.h"
#include "parksim/core/model/RobotDef.h"
#include "parksim/core/model/Trajectory.h"

namespace parksim {

enum class SteerMode {
  kFixedHorizon,  ///< drive toward the target for at most a fixed time (grows the tree)
  kToGoal,        ///< drive until the target pose is reached within tolerance, or give up
  /// Like kToGoal, but end exactly at the target (up to rounding; the last point's pose is the
  /// target itself). Trees whose nodes are joined by several edges over time (rewiring, goal
  /// trees) need this so that every edge into a node ends where the node's own edges start.
  kExact,
};

struct SteerResult {
  /// Starts at `from` with t = 0 and ends with zero wheel speeds. Each point's wheel speeds,
  /// held for its period and integrated exactly, give the next point's pose. Speeds stay within
  /// the robot's wheel speed limit, and each period's wheel speeds differ from the previous
  /// period's (from `from_wheels` for the first) by at most the acceleration limit times the
  /// period. In kToGoal and kExact the final stop obeys the acceleration limit too: the last
  /// period's wheel speeds are within one acceleration step of zero.
  Trajectory trajectory;
  /// kToGoal: the last pose is within the steering's goal tolerance of `to`.
  /// kExact: the last pose is `to`.
  /// kFixedHorizon: the target was reached before the horizon.
  bool reached = false;
};

/// The common end of steering functions that plan a whole path to `to` (rotate-translate-rotate,
/// Reeds-Shepp): in kFixedHorizon, a trajectory longer than `horizon_s` is cut after it (the
/// robot still moving, its last point with zero wheel speeds as every trajectory's) and
/// `reached` is false; otherwise the last pose is set to `to` itself, which the integration
/// missed by rounding only, so trajectories continuing from `to` join bit for bit.
void finishAtTarget(SteerResult& result, const Pose2& to, SteerMode mode, double horizon_s,
                    double period_s);

/// The steering functions' fixed horizon for the study's robot, s.
inline constexpr double kStudySteeringHorizon_s = 1.0;

/// A steering Def's horizon_s as used: itself when set, or when 0 (the defaults)
/// kStudySteeringHorizon_s in the robot's time (RobotDef::timeScale), so a tree grows by as
/// many of its robot's lengths per extension as the study robot's does in 1 s: 3.3 s for a
/// 4.25 m car at 3 m/s.
double steeringHorizon(double horizon_s, const RobotDef& robot);

class SteeringFunction {
 public:
  virtual ~SteeringFunction() = default;

  /// `from_wheels` are the wheel speeds the robot has on arrival at `from`; steering respects
  /// the acceleration limit from there. Every call ends in bounded time.
  virtual SteerResult steer(const Pose2& from, const WheelSpeeds& from_wheels, const Pose2& to,
                            SteerMode mode) const = 0;
};

}  // namespace parksim
