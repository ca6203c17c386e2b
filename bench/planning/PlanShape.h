#pragma once
// How a plan's path looks, in numbers (issue 18's "no zig-zag"): a path that zig-zags turns
// left, right, left... where a good one turns each way once per corner. Steering reversals
// count the changes of turning direction along the plan: the sign of the yaw rate over the
// periods that turn faster than a threshold (turning in place included), a change counted each
// time it differs from the previous turning period's.

#include "parksim/core/model/RobotDef.h"
#include "parksim/core/model/Trajectory.h"

namespace parksim::bench {

struct PlanShape {
  int steering_reversals = 0;
  double path_length_m = 0.0;
  /// steering_reversals / path_length_m, 1/m (0 for a path that does not move).
  double reversals_per_m = 0.0;
};

/// The shape of `plan`; periods turning slower than `min_turn_radps` do not count as turning.
PlanShape planShape(const Trajectory& plan, const RobotDef& robot, double min_turn_radps = 0.05);

}  // namespace parksim::bench
