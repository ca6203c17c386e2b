#pragma once
// What parksim's planners do with a path once they have found one: smooth it along its exact
// geometry (PathSmoother.h), time it to the fastest wheel speeds within the limits
// (TimeOptimalTiming.h), and report its cost. Public, so that a user's planner can finish its
// plans exactly as the built-in ones do.

#include <memory>

#include "parksim/planner/base/Planner.h"
#include "parksim/planner/motion/ClearanceValidator.h"

namespace parksim {

/// Finishes the solved `result` of a search on `problem`:
/// - when `smooth_geometry`: smooths the plan along its exact geometry at the problem's limits
///   (time-optimal timing) or at the robot's own limits with 0.1-s periods (study timing),
///   keeping it unless the smoothed plan validates as a whole;
/// - with time-optimal timing (problem.setup.timing): re-times it along its geometry and keeps
///   that unless it fails validation;
/// - sets result.cost to the plan's path cost (search cost weights) and makes the cost history
///   end with it.
/// For a car (RobotDef::isCar) instead: smooths as a car's path when `smooth_geometry`, then
/// makes the car's plan along it (CarPlanAlong.h) at the setup's headroom and period; its cost is
/// its duration or path cost (result.objective). When no car's plan validates, the result is
/// unsolved (kIterationLimit) with a message.
/// Collision queries and phase times are added to result.stats.
void finishPlan(const PlanningProblem& problem, bool smooth_geometry, PlanResult& result);

/// For a car (RobotDef::isCar): the validation its A* searches check moves with (and a car's
/// smoothing its shortcuts), a ClearanceValidator sparing the start and the goal (in both
/// headings when the goal takes either), so that the car's plan finishPlan makes along the path
/// found validates however its rows sample it. Null for a differential drive, whose search uses
/// problem.validator. The tree planners keep problem.validator: with the extra clearance their
/// Reeds-Shepp edges seldom enter a parallel slot 1.25 car lengths long; their plan along a path
/// that passes an obstacle within half a resolution may then fail its check, and they report no
/// plan.
std::unique_ptr<ClearanceValidator> carSearchValidation(const PlanningProblem& problem);

}  // namespace parksim
