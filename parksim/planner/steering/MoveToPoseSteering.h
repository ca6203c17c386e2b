#pragma once
// The polar-coordinate move-to-pose controller (Corke, "Robotics, Vision and Control", 4.1.1.4)
// used by the study as its steering function, with the study's defects corrected:
// - wheel speeds are the commands actually applied, after reversing and limiting, and the states
//   are their exact integral;
// - to-goal mode ends within the position and heading tolerance (a final turn in place fixes
//   the heading the slow beta mode leaves), or reports failure after max_duration_s;
// - wheel speed and wheel acceleration limits are respected, including the final stop;
// - kExact mode: the controller drives until the position is within turn_in_place_radius_m,
//   then a rotate-translate-rotate finisher closes the remaining fraction of a millimetre and
//   the heading exactly (where the controller would otherwise only turn in place).

#include "parksim/core/model/RobotDef.h"
#include "parksim/planner/motion/SteeringFunction.h"
#include "parksim/planner/steering/RotateTranslateRotateSteering.h"

namespace parksim {

struct MoveToPoseDef {
  double k_rho = 0.3;     ///< 1/s, distance gain (v = k_rho * rho)
  double k_alpha = 1.5;   ///< 1/s, bearing gain
  double k_beta = -0.3;   ///< 1/s, goal-heading gain
  double period_s = 0.1;  ///< control period: commands are held this long, s
  /// Length of a fixed-horizon trajectory, s; 0: 1 s for the study's robot, in proportion to
  /// the robot's time (steeringHorizon, SteeringFunction.h).
  double horizon_s = 0.0;
  double max_duration_s = 60.0;         ///< to-goal mode gives up after this long, s
  double position_tolerance_m = 0.001;  ///< to-goal mode: accepted distance to the target, m
  double heading_tolerance_rad = 0.5 * 3.14159265358979323846 / 180.0;  ///< accepted heading error
  /// Below this distance to the target, position is considered reached and the heading is
  /// corrected by turning in place, m. Must not exceed position_tolerance_m.
  double turn_in_place_radius_m = 0.0008;
  bool allow_reverse = true;  ///< drive backwards to targets behind the robot
};

class MoveToPoseSteering final : public SteeringFunction {
 public:
  MoveToPoseSteering(const RobotDef& robot, const MoveToPoseDef& def = {});

  SteerResult steer(const Pose2& from, const WheelSpeeds& from_wheels, const Pose2& to,
                    SteerMode mode) const override;

  const MoveToPoseDef& def() const { return def_; }

 private:
  RobotDef robot_;
  MoveToPoseDef def_;
  RotateTranslateRotateSteering finisher_;  // kExact's last millimetre
};

}  // namespace parksim
