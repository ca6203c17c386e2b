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
#include "parksim/core/model/Scenario.h"
#include "parksim/planner/motion/TimeOptimalTiming.h"

namespace parksim {

/// Lower bound on the duration of every plan from `from` to `to` whose wheel speeds keep
/// `limits` (rows limits.period_s apart, from and to rest), s. 0 when the poses are equal.
double freeSpaceDurationBound(const Pose2& from, const Pose2& to, const RobotDef& robot,
                              const TimingLimits& limits);

/// A car's (RobotDef::isCar, docs/cars.md): no plan of a car arrives sooner than its shortest
/// path, the Reeds-Shepp curve at its tightest turning radius (minTurningRadius), driven from
/// rest to rest in rows `period_s` apart at its speed and acceleration limits (the envelope
/// above, in m/s). It leaves out the steering: the time to turn the wheels (at the start they
/// are straight) and the stops at the curve's cusps, which a plan also spends. 0 when the
/// poses are equal.
double carFreeSpaceDurationBound(const Pose2& from, const Pose2& to, const RobotDef& car,
                                 double period_s);

/// The bound from `scenario`'s start to its goal (to the nearer of its two headings when the
/// goal takes either): a car's carFreeSpaceDurationBound in rows limits.period_s apart, a
/// differential drive's freeSpaceDurationBound within `limits`.
double scenarioFreeSpaceBound(const Scenario& scenario, const TimingLimits& limits);

}  // namespace parksim
