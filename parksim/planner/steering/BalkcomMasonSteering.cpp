#include "parksim/planner/steering/BalkcomMasonSteering.h"

#include <algorithm>

#include "parksim/core/io/Error.h"
#include "parksim/planner/steering/BalkcomMason.h"

namespace parksim {

BalkcomMasonSteering::BalkcomMasonSteering(const RobotDef& robot, const BalkcomMasonDef& def)
    : robot_(robot), def_(def) {
  def_.horizon_s = steeringHorizon(def.horizon_s, robot);
  if (!(def.period_s > 0.0) || !(def_.horizon_s > 0.0)) {
    throw Error("balkcom-mason steering: period and horizon must be positive");
  }
  if (!(def.speed_fraction > 0.0 && def.speed_fraction <= 1.0)) {
    throw Error("balkcom-mason steering: speed fraction must be in (0, 1]");
  }
  if (!(robot.max_wheel_speed_radps > 0.0) || !(robot.max_wheel_accel_radps2 > 0.0) ||
      !(robot.wheel_base_m > 0.0)) {
    throw Error("balkcom-mason steering: wheel base, speed and accel limits must be positive");
  }
}

std::vector<PathPiece> BalkcomMasonSteering::pieces(const Pose2& from, const Pose2& to) const {
  return piecesOf(balkcomMasonPath(from, to, 0.5 * robot_.wheel_base_m), robot_);
}

SteerResult BalkcomMasonSteering::steer(const Pose2& from, const WheelSpeeds& from_wheels,
                                        const Pose2& to, SteerMode mode) const {
  const TimingLimits limits{def_.speed_fraction * robot_.max_wheel_speed_radps,
                            robot_.max_wheel_accel_radps2, def_.period_s};
  return steerThroughPieces(from, from_wheels, to, mode, robot_, limits, def_.horizon_s,
                            [&](const Pose2& at_rest) { return pieces(at_rest, to); });
}

}  // namespace parksim
