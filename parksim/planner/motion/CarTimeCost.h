#pragma once
// How long a car's path of constant-curvature pieces takes, estimated in O(1) per piece, for
// the car search and a car's smoothing, which compare many candidates (the exact timing is
// CarTiming.h's): each piece at the fastest speed its curvature allows, plus what each junction
// loses. Where the curvature jumps between pieces driven one way, the car passes a clothoid
// (CarPath.h) as long as the room on either side allows, at the speed that turns its steering at
// the rate limit there: slowing from V to that speed v and back costs (V - v)^2 / (A V), driving
// the clothoid slower 2h (1/v - 1/V). A gear change stops (V / A), steers standing (|d steer| /
// rate) and costs the search's penalty on top. The start and the end ramp from and to rest
// (V / 2A each) and the car first steers standing from straight wheels.

#include "parksim/core/model/RobotDef.h"
#include "parksim/planner/motion/CarTiming.h"

namespace parksim {

class CarTimeCost {
 public:
  /// `gear_change_penalty_s` (>= 0) is added to every gear change.
  CarTimeCost(const RobotDef& car, const CarLimits& limits, double gear_change_penalty_s = 0.0);

  /// Time to drive `length_m` at curvature `kappa` at the fastest speed it allows, s.
  double pieceTime(double length_m, double kappa) const;

  /// Time lost where the car goes from driving `direction_a` (+1, -1; 0: at rest, the start or
  /// the end) at curvature `kappa_a` to driving `direction_b` at `kappa_b`, with `room_m` on
  /// either side for a clothoid, s.
  double junctionTime(int direction_a, double kappa_a, int direction_b, double kappa_b,
                      double room_m) const;

  const CarLimits& limits() const { return limits_; }

 private:
  RobotDef car_;
  CarLimits limits_;
  double gear_change_penalty_s_;
};

}  // namespace parksim
