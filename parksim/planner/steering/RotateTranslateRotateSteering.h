#pragma once
// Rotate-translate-rotate steering for a differential drive: turn in place to face the target
// (or to face away from it and reverse, whichever needs less turning in total), drive straight
// to it, turn in place to the target heading. It reaches the target pose exactly (up to
// rounding), because every phase follows a rest-to-rest speed profile (SpeedProfile.h) whose
// commands integrate exactly to the phase's angle or distance.
//
// Wheel speed and wheel acceleration limits hold throughout: from any arrival wheel speeds the
// robot first brakes, each phase ramps up and down by whole acceleration steps with half steps
// at its ends, so consecutive phases, the start and the final stop all stay within the limit.

#include "parksim/core/model/RobotDef.h"
#include "parksim/planner/motion/SteeringFunction.h"

namespace parksim {

struct RotateTranslateRotateDef {
  double period_s = 0.1;  ///< control period: commands are held this long, s
  /// Length of a fixed-horizon trajectory, s; 0: 1 s for the study's robot, in proportion to
  /// the robot's time (steeringHorizon, SteeringFunction.h).
  double horizon_s = 0.0;
  /// Fraction of the robot's wheel speed limit the phases may use, in (0, 1].
  double speed_fraction = 1.0;
  /// Fraction of the robot's wheel acceleration limit the phases may use, in (0, 1].
  double accel_fraction = 1.0;
};

class RotateTranslateRotateSteering final : public SteeringFunction {
 public:
  RotateTranslateRotateSteering(const RobotDef& robot, const RotateTranslateRotateDef& def = {});

  /// kToGoal and kExact both end exactly at `to`, at rest; kFixedHorizon is the same plan cut
  /// after horizon_s (`reached` when the whole plan fits).
  SteerResult steer(const Pose2& from, const WheelSpeeds& from_wheels, const Pose2& to,
                    SteerMode mode) const override;

  const RotateTranslateRotateDef& def() const { return def_; }

 private:
  RobotDef robot_;
  RotateTranslateRotateDef def_;
};

}  // namespace parksim
