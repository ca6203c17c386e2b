#pragma once
// A car's plan along a path of constant-curvature pieces (the searches', the trees' Reeds-Shepp
// edges', smoothing's): the pieces become sections (CarPath.h); each curvature jump between
// pieces driven the same way becomes a clothoid long enough to pass it at the speed limit, the
// path is corrected to end where it did, and it is timed (CarTiming.h) and checked by the
// motion validator as a whole. Clothoids move the path off the checked pieces by up to a few
// decimetres, so a plan that fails (or ends too far from the path's end) is made again with
// clothoids half as long, and so on down to none: the car then stops at each jump and steers
// standing, on the pieces' own geometry, which the planner checked.

#include <optional>
#include <vector>

#include "parksim/core/geometry/Pose2.h"
#include "parksim/core/model/RobotDef.h"
#include "parksim/core/model/Trajectory.h"
#include "parksim/planner/motion/CarTiming.h"
#include "parksim/planner/motion/MotionValidator.h"
#include "parksim/planner/motion/TimeOptimalTiming.h"

namespace parksim {

/// The plan that drives `pieces` from `start` (see the file comment), ending within
/// `end_tolerance_m` of where they end and at their heading (to end_tolerance_m per metre of
/// the car's axle distance); nothing when not even the pieces' own geometry validates.
/// `clothoid_share`, when given, is told the share of the full clothoids' length the plan has
/// (1: every jump passed at the speed limit, 0: stops at every jump).
std::optional<Trajectory> carPlanAlong(const Pose2& start, const std::vector<PathPiece>& pieces,
                                       const RobotDef& car, const CarLimits& limits,
                                       const MotionValidator& validator, double end_tolerance_m,
                                       double* clothoid_share = nullptr);

/// How long carPlanAlong's plan with full clothoids would take, s (without correcting the end
/// or validating): what a car's smoothing compares paths by.
double carPlanDuration(const std::vector<PathPiece>& pieces, const RobotDef& car,
                       const CarLimits& limits);

}  // namespace parksim
