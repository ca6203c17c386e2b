#pragma once
// The physical limit of any plan between two poses: no plan, whatever the obstacles, arrives
// sooner than this within the timing's wheel-speed limit V, its acceleration limit A and its
// control period dt. A path's time at full wheel speed is its Balkcom-Mason cost over r V
// (BalkcomMason.h), so any plan's wheels turn at least W = cost / r (the faster wheel's travel,
// summed). A plan of n periods from rest to rest turns its faster wheel by at most
// dt sum_k min(V, k A dt, (n + 1 - k) A dt) (one acceleration step per period from rest and to
// rest): the bound is the fewest periods whose envelope reaches W.

#include "parksim/core/geometry/Pose2.h"
#include "parksim/core/model/RobotDef.h"
#include "parksim/planner/motion/TimeOptimalTiming.h"

namespace parksim {

/// Lower bound on the duration of every plan from `from` to `to` whose wheel speeds keep
/// `limits` (rows limits.period_s apart, from and to rest), s. 0 when the poses are equal.
double freeSpaceDurationBound(const Pose2& from, const Pose2& to, const RobotDef& robot,
                              const TimingLimits& limits);

}  // namespace parksim
