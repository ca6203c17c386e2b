#pragma once
// Shortcut smoothing (the study's 3(c)(3)): replace the part of a plan between two waypoints by
// one direct steering trajectory when that is collision-free and makes the plan cheaper.
//
// Waypoints are the poses where the plan's segments join. A shortcut from waypoint i to
// waypoint j is steered in kExact mode (kToGoal when j is the goal), so it ends exactly where
// the rest of the plan starts. Segments after it that were steered from their predecessor's
// arrival wheel speeds cannot follow a stop, so they are re-steered from rest between the same
// waypoints; segments already steered from rest are kept. Every new segment is validated before
// a shortcut is accepted, so the smoothed plan consists of validated segments only (the planner
// still validates the joined result as a whole).

#include <random>
#include <vector>

#include "parksim/core/model/RobotDef.h"
#include "parksim/planner/motion/MotionValidator.h"
#include "parksim/planner/motion/PathCost.h"
#include "parksim/planner/motion/SteeringFunction.h"
#include "parksim/planner/tree/PathSegment.h"

namespace parksim {

struct SmoothingStats {
  int attempts = 0;   ///< shortcuts tried
  int accepted = 0;   ///< shortcuts that made the plan cheaper and were kept
  int validated = 0;  ///< new segments checked by the motion validator
};

class ShortcutSmoother {
 public:
  ShortcutSmoother(const RobotDef& robot, const SteeringFunction& steering,
                   const MotionValidator& validator, const CostWeights& weights);

  /// `segments` run from the start (at rest) to within the goal region around `goal`, which is
  /// the pose the last segment steers to. Tries `attempts` random shortcuts drawn from `rng` and
  /// returns the cheapest plan found (the input when nothing helped).
  std::vector<PathSegment> smooth(std::vector<PathSegment> segments, const Pose2& goal,
                                  int attempts, std::mt19937_64& rng,
                                  SmoothingStats* stats = nullptr) const;

 private:
  RobotDef robot_;
  const SteeringFunction& steering_;
  const MotionValidator& validator_;
  CostWeights weights_;
};

}  // namespace parksim
