#pragma once
// State validity for the planner: does the robot's footprint at a pose overlap an obstacle?
// Implemented by the Bullet collision adapter (collision/); the planner sees only this.

#include <string>
#include <vector>

#include "parksim/core/geometry/Pose2.h"

namespace parksim {

class FootprintChecker {
 public:
  virtual ~FootprintChecker() = default;

  /// True when the footprint at `pose`, grown by `margin_m` (>= 0) on every side, overlaps
  /// no obstacle. Touching is not overlapping.
  virtual bool isFree(const Pose2& pose, double margin_m = 0.0) const = 0;

  /// Names of the obstacles the grown footprint overlaps, for messages ("the footprint overlaps
  /// dropped_box"); a checker that cannot name them returns none.
  virtual std::vector<std::string> overlapping(const Pose2& pose, double margin_m = 0.0) const {
    (void)pose;
    (void)margin_m;
    return {};
  }
};

}  // namespace parksim
