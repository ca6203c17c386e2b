#pragma once
// parksim's own verdict on a planned path, whichever library planned it. The path is given as
// poses dense enough that no point of the footprint moves more than `max_step_m` between two
// consecutive ones; every pose must have its reference point inside the lot and a footprint
// that overlaps nothing (margin 0, exact box-box test). An overlap this misses is shallower
// than max_step_m / 2. A path that is not that dense is rejected rather than trusted.

#include <cstddef>
#include <vector>

#include "parksim/collision/BulletCollisionWorld.h"
#include "parksim/core/geometry/Pose2.h"
#include "parksim/core/model/RobotDef.h"
#include "parksim/core/model/Scenario.h"
#include "parksim/core/model/Trajectory.h"

namespace parksim::bench {

struct PathCheckDef {
  /// Largest distance any footprint point may move between two checked poses, m.
  double max_step_m = 0.0002;
  /// Also compute the smallest clearance along the path (costs one distance query per pose).
  bool clearance = true;
};

struct PathCheck {
  bool valid = false;            ///< dense enough, inside the lot and free at every pose
  bool dense_enough = false;     ///< every step within max_step_m
  std::size_t poses = 0;         ///< poses checked
  std::size_t first_bad = 0;     ///< index of the first pose outside the lot or overlapping
  double max_step_m = 0.0;       ///< largest footprint-point step found between two poses, m
  double length_m = 0.0;         ///< polyline length of the reference point, m
  double min_clearance_m = 0.0;  ///< smallest clearance over the poses, m (0 when not valid,
                                 ///< NaN when not computed)
};

/// Upper bound of how far any footprint point moves between two poses: |dp| + r |dtheta|,
/// with r the farthest footprint point from the reference point.
double footprintStep(const Pose2& a, const Pose2& b, double footprint_radius_m);

/// Samples a trajectory along its exact arcs so that footprint points move at most
/// max_step_m between consecutive poses. The first and last poses are the trajectory's.
std::vector<Pose2> densify(const Trajectory& traj, const RobotDef& robot, double max_step_m);

/// Checks dense poses against the scenario's obstacles and lot with `world`.
PathCheck checkPath(const std::vector<Pose2>& poses, const Scenario& scenario,
                    const BulletCollisionWorld& world, const PathCheckDef& def = {});

/// Direction reversals along dense poses: the sign of the motion along the heading, counted
/// once the robot has moved 0.1 mm the other way (so turning in place and jitter do not count).
int countCusps(const std::vector<Pose2>& poses);

}  // namespace parksim::bench
