#pragma once
// A plan as the planners build it: steering trajectories placed end to end. Each segment
// starts at the pose where the previous one ends. Segments steered from the previous one's
// arrival wheel speeds join directly; segments steered from rest may follow any segment that
// ends with a legal stop, and where the wheel speeds across such a junction would change by more
// than one acceleration step, the robot stands still for one period first.

#include <vector>

#include "parksim/core/model/RobotDef.h"
#include "parksim/core/model/Trajectory.h"
#include "parksim/planner/motion/PathCost.h"

namespace parksim {

struct PathSegment {
  Trajectory trajectory;
  /// Steered with zero arrival wheel speeds: may follow any segment that ends with a legal stop.
  bool from_rest = false;
};

/// Wheel speeds of the last period that moves, i.e. what the robot arrives with at the end.
/// Zero for a trajectory of one point.
WheelSpeeds arrivalWheels(const Trajectory& traj);

/// True when wheel speeds `b` may follow `a` one period later under the acceleration limit.
bool withinAccelStep(const WheelSpeeds& a, const WheelSpeeds& b, const RobotDef& robot,
                     double period_s);

/// True when the trajectory's last period can step to zero wheel speeds: a legal stop.
bool endsWithLegalStop(const Trajectory& traj, const RobotDef& robot);

/// Joins the segments into one trajectory on one clock (see the file comment for junctions).
Trajectory joinSegments(const std::vector<PathSegment>& segments, const RobotDef& robot);

/// Cost of the joined segments, computed piece by piece, m.
double segmentsCost(const std::vector<PathSegment>& segments, const RobotDef& robot,
                    const CostWeights& w);

}  // namespace parksim
