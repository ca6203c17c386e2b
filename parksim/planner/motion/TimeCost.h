#pragma once
// How long a path of pieces (TimeOptimalTiming.h) takes, estimated in O(1) per piece, for the
// searches and smoothing that compare many candidate paths: each piece at full speed (the
// faster wheel at the timing's wheel-speed limit: for any arc or spin that is (|d| + h |dtheta|)
// / (r V), the Balkcom-Mason metric of BalkcomMason.h) plus, at each junction, the time lost
// slowing down to the speed at which the wheels may change direction there and speeding up
// again: passing at wheel speed e costs (V - e)^2 / (A V) more than cruising through, with
// e = min(V, A dt / J) and J the largest change of a wheel's share of the speed (2 at a cusp or
// between turning in place and driving; from and to rest one ramp, half that). That is the loss of
// continuous ramps at the acceleration limit A into and out of the junction; the exact timing
// (timePieces) is within a few periods of the estimate, and never below the time at full speed.

#include <vector>

#include "parksim/core/model/DiffDrive.h"
#include "parksim/planner/motion/TimeOptimalTiming.h"

namespace parksim {

class TimeCostModel {
 public:
  explicit TimeCostModel(const TimingLimits& limits);

  /// Time to drive `piece` with its faster wheel at the speed limit, s.
  double pieceTime(const PathPiece& piece) const { return piece.travel_rad / speed_; }
  /// Time lost at a junction from wheel-speed direction `a` to `b` (PathPiece::direction; zero
  /// wheel speeds stand for rest), s.
  double junctionTime(const WheelSpeeds& a, const WheelSpeeds& b) const;
  /// Estimated duration of `pieces` from rest to rest, s: pieces at full speed, every junction's
  /// loss, and the ramps from and to rest.
  double duration(const std::vector<PathPiece>& pieces) const;

  const TimingLimits& limits() const { return limits_; }

 private:
  TimingLimits limits_;
  double speed_;  // V, rad/s
  double step_;   // A dt, rad/s
};

}  // namespace parksim
