#pragma once
// Planners by name: parksim's own (builtInPlanners) and those a front-end adds from plugins
// (parksim/usercode/). `--planner NAME`, a sweep's `planners:` axis, Python's plan(planner=...)
// and parksim-bench all look names up here, so a plugin's planner is selected exactly as a
// built-in one.

#include <memory>
#include <string>
#include <vector>

#include "parksim/core/model/Scenario.h"
#include "parksim/core/params/ParamMap.h"
#include "parksim/planner/base/Planner.h"

namespace parksim {

/// Planners by name (ComponentRegistry.h): add, find, names, make.
using PlannerRegistry = ComponentRegistry<PlannerEntry>;

/// parksim's own planners: rrt, rrt-goal-connect, rrt-star, rrt-connect (TreePlanners.cpp),
/// hybrid-a-star (HybridAStarPlanner.cpp), time-a-star (TimeAStarPlanner.cpp) and car-a-star
/// (CarAStarPlanner.cpp). Built once, never changed.
const PlannerRegistry& builtInPlanners();

/// The planner that plans for `robot` when `planner` is asked for: itself, except that the
/// A* planner costed by time is each drive's own: a car (RobotDef::isCar), which cannot turn in
/// place, is planned by car-a-star when time-a-star (the default planner, whose moves turn in
/// place) is asked for, and a differential drive by time-a-star when car-a-star is.
/// resolvedPlanSetup applies it.
std::string plannerFor(const std::string& planner, const RobotDef& robot);

/// Area of the study's lot (1.8 x 1.2 m), the unit of the default budgets' scaling, m^2.
inline constexpr double kStudyLotAreaM2 = 1.8 * 1.2;

/// The lot's area in study lots, both measured in their robot's size: lot area / size^2 over the
/// study lot's area / the study robot's size^2. A search grows a tree or a grid in steps and
/// cells of the robot's size (TreePlannerDef, TimeAStarDef, HybridAStarDef), so this is how
/// much more there is to search than in the study: 1 for the study's robot in its lot, 1.27 for
/// a 4.25 m car in an 86 x 80 m warehouse, 0.05 for the car in an 18.7 x 14.4 m lot.
double lotSizeInStudyLots(const Scenario& scenario);

/// `base` iterations times max(1, lotSizeInStudyLots(scenario)), rounded up and capped at
/// 10^6, so budgets grow with the space to search and stay bounded (docs/limits.md). For the
/// study's robot, base x max(1, lot area / 2.16 m^2).
int lotScaledBudget(int base, const Scenario& scenario);

/// `info`'s budget for `scenario` (PlannerInfo::default_budget, or lotScaledBudget(2000, ...)).
int defaultIterationBudget(const PlannerInfo& info, const Scenario& scenario);

}  // namespace parksim
