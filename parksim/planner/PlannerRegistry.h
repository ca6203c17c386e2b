#pragma once
// Planners by name: parksim's own (builtInPlanners) and those a front-end adds from plugins
// (parksim/plugin/). `--planner NAME`, a sweep's `planners:` axis, Python's plan(planner=...)
// and parksim-bench all look names up here, so a plugin's planner is selected exactly as a
// built-in one.

#include <memory>
#include <string>
#include <vector>

#include "parksim/core/ParamMap.h"
#include "parksim/core/Scenario.h"
#include "parksim/planner/Planner.h"

namespace parksim {

/// Planners by name (ComponentRegistry.h): add, find, names, make.
using PlannerRegistry = ComponentRegistry<PlannerEntry>;

/// parksim's own planners: rrt, rrt-goal-connect, rrt-star, rrt-connect (TreePlanners.cpp),
/// hybrid-a-star (HybridAStarPlanner.cpp) and time-a-star (TimeAStarPlanner.cpp). Built once,
/// never changed.
const PlannerRegistry& builtInPlanners();

/// Area of the study's lot (1.8 x 1.2 m), the unit of the default budgets' scaling, m^2.
inline constexpr double kStudyLotAreaM2 = 1.8 * 1.2;

/// `base` iterations times max(1, lot area / the study lot's area), rounded up and capped at
/// 10^6, so budgets grow with the space to search and stay bounded (docs/limits.md).
int lotScaledBudget(int base, const LotBounds& lot);

/// `info`'s budget for `scenario` (PlannerInfo::default_budget, or lotScaledBudget(2000)).
int defaultIterationBudget(const PlannerInfo& info, const Scenario& scenario);

}  // namespace parksim
