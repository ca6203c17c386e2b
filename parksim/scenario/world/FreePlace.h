#pragma once
// Free places for a robot in a lot with obstacles, found without a fixed lattice: a best-first
// branch and bound over the lot. A square of the lot whose centre's clearance plus the square's
// half-diagonal is below the room asked for holds no free place (clearance moves at most as far
// as the robot does) and is dropped; the others are split until a centre is free or the square
// is smaller than kFreePlaceResolution of the room. Used by `parksim import` for the
// placeholders of start and goal.

#include <functional>
#include <optional>

#include "parksim/core/model/Scenario.h"

namespace parksim {

/// The smallest square searched, as a fraction of the room: a free region that holds a disc of
/// this radius (in reference-point positions) is found.
inline constexpr double kFreePlaceResolution = 1.0 / 32.0;
/// Clearance evaluations one search makes at most before it gives up.
inline constexpr int kMaxFreePlaceChecks = 200000;

struct FreePlaceQuery {
  /// Room around the footprint, m: a place is free when placementProblem(scenario, pose,
  /// room_m) finds nothing.
  double room_m = 0.0;
  /// Search towards the lot's upper right (largest x + y) instead of its lower left.
  bool from_upper_right = false;
  /// A further condition a free place must meet (none: any free place).
  std::function<bool(const Pose2&)> accept;
};

/// A free place at heading 0 as near the lot's lower-left (or upper-right) corner as the search
/// finds (within the smallest square), or nothing when the lot has none. Deterministic.
std::optional<Pose2> findFreePlace(const Scenario& scenario, const FreePlaceQuery& query);

/// The signed clearance of the robot's footprint at `pose` from the obstacles that block it, m:
/// the least separating-axis separation, negative when overlapping; +infinity without
/// obstacles. Moves by at most the distance the pose moves (headings equal).
double footprintClearance(const Scenario& scenario, const Pose2& pose);

}  // namespace parksim
