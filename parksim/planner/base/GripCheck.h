#pragma once
// The grip a plan asks of the tyres, against what they have: a plan that needs more is refused
// before it is driven (plan_invalid, naming the time, the force and the grip), instead of
// ending off its goal with "contact" after the wheels slipped. The plan's limits are checked
// against the motors' torque when the world is read (PhysicalRanges.h's driveProblem); this
// checks each row of the plan itself.
//
// The model (docs/limits.md, "Grip"): the robot's weight rests on its wheels in equal shares
// (two for a differential drive, four for a car; the passive sliders carry none), each wheel's
// grip is wheel_friction x ground_friction (Bullet's combined friction) times its share. A
// wheel's demand is the vector sum of
// - its longitudinal force: half of mass x the plan's acceleration, and for a differential
//   drive plus or minus the torque that turns the robot, yaw inertia x yaw acceleration over
//   the wheel base (the chassis a uniform box about the axle's middle, the wheels point
//   masses, as wheelDemand); a car's steered wheels turn it;
// - its lateral force: its share of mass x speed x yaw rate (the centripetal force).
// Accelerations are the rows' wheel-speed steps over the period they start, as the plan
// check's acceleration limit takes them (from rest at the start, to rest at the end).

#include <optional>

#include "parksim/core/model/Scenario.h"
#include "parksim/core/model/Trajectory.h"
#include "parksim/planner/base/PlanCheck.h"

namespace parksim {

/// What the wheels' grip gives and what a robot is made of, for the grip check.
struct GripModel {
  double mass_kg = 0.0;      ///< chassis and wheels
  double yaw_inertia = 0.0;  ///< kg m^2, about the driven axle's middle
  int wheels_bearing = 2;    ///< wheels the weight rests on
  double grip_n = 0.0;       ///< each wheel's, N
};

GripModel gripModel(const Scenario& scenario);

/// The first row of `plan` (well-formed, malformedPlan) at which a driven wheel needs more
/// grip than it has (beyond rounding), or nothing.
std::optional<PlanViolation> gripViolation(const Scenario& scenario, const Trajectory& plan);

}  // namespace parksim
