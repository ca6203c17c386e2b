#pragma once
// Reeds-Shepp steering: the shortest path of forward and reverse arcs of a chosen radius and
// straights between two poses (Reeds and Shepp 1990; the curve itself comes from OMPL's
// ReedsSheppStateSpace, which tries all 48 words, loaded on first use: OmplPlugin.h). The arcs
// and straights become exact pieces (TimeOptimalTiming.h) driven at the wheel-speed and
// acceleration limits, stopping at every cusp, so the trajectory ends exactly at the target (up
// to rounding) at rest.
//
// A car's arcs are at least its minimum turning radius (RobotDef::minTurningRadius), whatever
// the Def says.
//
// A diff-drive robot could also turn on the spot (radius 0: rotate-translate-rotate does that);
// Reeds-Shepp curves need a radius > 0. A radius at or above half the wheel base keeps both
// wheels turning the same way along every arc.

#include <memory>
#include <vector>

#include "parksim/core/model/RobotDef.h"
#include "parksim/planner/motion/SteeringFunction.h"
#include "parksim/planner/motion/TimeOptimalTiming.h"

namespace parksim {

struct ReedsSheppDef {
  double turning_radius_m = 0.05;  ///< radius of every arc, m (> 0)
  double period_s = 0.1;           ///< control period: commands are held this long, s
  /// Length of a fixed-horizon trajectory, s; 0: 1 s for the study's robot, in proportion to
  /// the robot's time (steeringHorizon, SteeringFunction.h).
  double horizon_s = 0.0;
  /// Fraction of the robot's wheel speed limit the steering may use, in (0, 1].
  double speed_fraction = 1.0;
};

class ReedsSheppSteering final : public SteeringFunction {
 public:
  ReedsSheppSteering(const RobotDef& robot, const ReedsSheppDef& def = {});
  ~ReedsSheppSteering() override;
  ReedsSheppSteering(const ReedsSheppSteering&) = delete;
  ReedsSheppSteering& operator=(const ReedsSheppSteering&) = delete;

  /// kToGoal and kExact both end exactly at `to`, at rest; kFixedHorizon is the same path cut
  /// after horizon_s (`reached` when the whole path fits). From moving wheels the robot brakes
  /// first, then follows the curve from where it stopped.
  SteerResult steer(const Pose2& from, const WheelSpeeds& from_wheels, const Pose2& to,
                    SteerMode mode) const override;

  /// The shortest curve from `from` to `to` as pieces (no timing).
  std::vector<PathPiece> pieces(const Pose2& from, const Pose2& to) const;
  /// Length of the shortest curve, m.
  double distance(const Pose2& from, const Pose2& to) const;

  const ReedsSheppDef& def() const { return def_; }

 private:
  struct Curve;  // OMPL's state space, through the plugin
  RobotDef robot_;
  ReedsSheppDef def_;
  std::unique_ptr<Curve> curve_;
};

}  // namespace parksim
