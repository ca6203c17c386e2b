#pragma once
// Balkcom-Mason steering: the fastest path of the differential drive between two poses in free
// space, turns in place alternating with straight drives (BalkcomMason.h), driven as exact pieces
// at the wheel-speed and acceleration limits (TimeOptimalTiming.h). It ends exactly at the target
// (up to rounding), at rest. This is the steering that fits the robot: Reeds-Shepp curves are
// the fastest paths of a car that cannot turn in place.

#include <vector>

#include "parksim/core/model/RobotDef.h"
#include "parksim/planner/motion/SteeringFunction.h"
#include "parksim/planner/motion/TimeOptimalTiming.h"

namespace parksim {

struct BalkcomMasonDef {
  double period_s = 0.1;  ///< control period: commands are held this long, s
  /// Length of a fixed-horizon trajectory, s; 0: 1 s for the study's robot, in proportion to
  /// the robot's time (steeringHorizon, SteeringFunction.h).
  double horizon_s = 0.0;
  /// Fraction of the robot's wheel speed limit the steering may use, in (0, 1].
  double speed_fraction = 1.0;
};

class BalkcomMasonSteering final : public SteeringFunction {
 public:
  explicit BalkcomMasonSteering(const RobotDef& robot, const BalkcomMasonDef& def = {});

  /// kToGoal and kExact both end exactly at `to`, at rest; kFixedHorizon is the same path cut
  /// after horizon_s (`reached` when the whole path fits). From moving wheels the robot brakes
  /// first, then follows the path from where it stopped.
  SteerResult steer(const Pose2& from, const WheelSpeeds& from_wheels, const Pose2& to,
                    SteerMode mode) const override;

  /// The fastest path from `from` to `to` as pieces (no timing).
  std::vector<PathPiece> pieces(const Pose2& from, const Pose2& to) const;

  const BalkcomMasonDef& def() const { return def_; }

 private:
  RobotDef robot_;
  BalkcomMasonDef def_;
};

}  // namespace parksim
