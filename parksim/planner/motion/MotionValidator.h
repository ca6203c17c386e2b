#pragma once
// Motion validation without gaps. Between two trajectory points the robot follows an exact arc;
// the validator checks poses along it so densely that no point of the footprint moves more than
// `resolution_m` between two checks, and checks the footprint grown by resolution_m / 2. Every
// point of the swept area between two checked poses then lies inside one of the grown
// footprints, so a trajectory accepted here is free at every instant (conservative by at most
// resolution_m / 2). The reference point must also stay inside the lot bounds, shrunk by
// resolution_m / 2 for the same reason: the study's lot has no boundary walls, and without this a
// trajectory could leave the lot to get around its obstacles.

#include <optional>
#include <vector>

#include "parksim/core/model/FootprintChecker.h"
#include "parksim/core/model/RobotDef.h"
#include "parksim/core/model/Scenario.h"
#include "parksim/core/model/Trajectory.h"

namespace parksim {

struct MotionValidatorDef {
  /// Largest distance any footprint point travels between two checks, m; also twice the
  /// clearance every checked pose keeps. 0 (the default): motionCheckResolution(robot)
  /// (core/model/Scenario.h), 1 mm for the study's 85 mm robot and in proportion to any robot's
  /// size, so a car's plans keep as much clearance for its size as the study robot's do.
  double resolution_m = 0.0;
};

/// `def` with its automatic resolution made for `robot` (what MotionValidator uses and result
/// files record).
MotionValidatorDef resolvedValidation(const MotionValidatorDef& def, const RobotDef& robot);

/// Not thread-safe: it counts queries and reuses a scratch buffer; use one per thread.
class MotionValidator {
 public:
  MotionValidator(const FootprintChecker& checker, const RobotDef& robot, const LotBounds& lot,
                  const MotionValidatorDef& def = {});

  /// True when the whole trajectory, including its first and last pose, is collision-free.
  /// The samples are checked coarse to fine (every 64th first), which finds collisions early;
  /// the answer does not depend on the order.
  bool isValid(const Trajectory& traj) const;

  /// Where the trajectory first fails the same check, in time order (every sample), or nothing
  /// when isValid(traj) holds: for saying where a plan goes wrong (PlanCheck.h).
  struct Failure {
    double t_s = 0.0;          ///< time of the first invalid sample, on the trajectory's clock, s
    Pose2 pose;                ///< the pose there
    bool outside_lot = false;  ///< the reference point leaves the lot (less the margin)
  };
  std::optional<Failure> firstFailure(const Trajectory& traj) const;

  /// The check made for a single state: grown footprint free, reference point inside the lot.
  bool isValid(const Pose2& pose) const;

  /// True when the reference point keeps the margin from the lot edge that isValid requires;
  /// tells "too close to the lot edge" apart from "collides".
  bool insideLot(const Pose2& pose) const { return inner_.contains(pose.x, pose.y); }

  /// Number of footprint queries made so far.
  long queries() const { return queries_; }

  /// The definition as used: the resolution resolved for the robot.
  const MotionValidatorDef& def() const { return def_; }

 private:
  const FootprintChecker& checker_;
  RobotDef robot_;
  LotBounds inner_;  // lot bounds shrunk by resolution_m / 2 (less kPlacementTolerance_m)
  MotionValidatorDef def_;
  double radius_;  // farthest footprint point from the reference point, m
  mutable long queries_ = 0;

  // Samples of one trajectory period (scratch, reused between calls).
  struct Period {
    Twist twist;
    double dt;
    int samples;  // checked poses in the period, the first at its start
    long first;   // index of its first sample in the trajectory
  };
  static constexpr long kCoarsestStride = 64;
  /// Fills periods_ for `traj` (non-empty); returns the number of samples.
  long prepare(const Trajectory& traj) const;
  /// Sample `idx` of the trajectory prepare() was last given, and its time; `period` only
  /// moves forward, as indices do within one pass.
  Pose2 sample(const Trajectory& traj, long idx, std::size_t& period, double* t_s = nullptr) const;
  mutable std::vector<Period> periods_;
};

}  // namespace parksim
