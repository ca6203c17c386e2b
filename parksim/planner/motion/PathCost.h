#pragma once
// The cost the planners minimise and compare: path length, plus a penalty per metre driven in
// reverse, plus a penalty per cusp (change of driving direction). Kept additive over pieces of
// a path, with the cusp at each junction counted from the directions the pieces start and end
// in, so a tree can carry costs edge by edge and still agree with the joined trajectory.

#include <vector>

#include "parksim/core/model/RobotDef.h"
#include "parksim/core/model/Trajectory.h"

namespace parksim {

struct CostWeights {
  double reverse_penalty = 0.0;  ///< extra cost per metre driven in reverse, m per m
  double cusp_penalty_m = 0.0;   ///< cost of one change of driving direction, m
};

/// What the cost of a trajectory piece depends on.
struct MotionSummary {
  double length_m = 0.0;   ///< distance travelled by the reference point, m
  double reverse_m = 0.0;  ///< part of it driven backwards, m
  int cusps = 0;           ///< direction changes inside the piece
  /// Driving direction of the first and the last period that moves (+1 forward, -1 reverse),
  /// 0 when the piece only turns in place. Speeds below 0.1 mm/s count as turning in place, as
  /// in Trajectory::cusps.
  int first_direction = 0;
  int last_direction = 0;
};

MotionSummary summarizeMotion(const Trajectory& traj, const RobotDef& robot);

/// 1 when a path whose last motion was in direction `before` continues in direction `after`
/// the other way, else 0 (0 means no motion and never makes a cusp).
inline int junctionCusps(int before, int after) {
  return before != 0 && after != 0 && before != after ? 1 : 0;
}

/// Direction of the last motion after appending a piece to a path that last moved `before`.
inline int lastDirectionAfter(int before, const MotionSummary& piece) {
  return piece.last_direction != 0 ? piece.last_direction : before;
}

/// Cost of a piece on its own (no junction cusp), m.
double motionCost(const MotionSummary& m, const CostWeights& w);

/// Cost of a whole trajectory, m. Equals the sum of its pieces' costs plus their junction cusps.
double trajectoryCost(const Trajectory& traj, const RobotDef& robot, const CostWeights& w);

}  // namespace parksim
