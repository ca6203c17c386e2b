#pragma once
// Runs one parksim planner the way the planning command does (planScenario with the study's
// controller as steering) and turns the result into a bench.csv row, with the path checked by
// parksim's exact path check like every other library's.

#include <cstdint>

#include "bench/planning/PathCheck.h"
#include "parksim/collision/BulletCollisionWorld.h"
#include "parksim/core/model/Scenario.h"
#include "parksim/planner/base/PlanScenario.h"
#include "parksim/results/reports/BenchRecord.h"

namespace parksim::bench {

struct ParksimRunDef {
  PlanSetup setup;  ///< planner, seed, iteration and wall-time budgets, steering, validation
  PathCheckDef check;
  /// Where setup.planner is looked up: parksim's own, or with plugins' (--plugin).
  const PlannerRegistry* planners = &builtInPlanners();
};

/// Plans `scenario` with `def.setup` against `world` and checks the path. The record's planner
/// is the planner kind, with "+smooth" when smoothing is on; its space is the steering kind.
BenchRecord runParksim(const Scenario& scenario, const BulletCollisionWorld& world,
                       const ParksimRunDef& def);

/// "iterations=N", "time=Ss" or both joined with '+': what ends a parksim run. INT_MAX
/// iterations (a run budgeted by time alone) is left out.
std::string budgetName(const SearchDef& planner);

/// CPU time the calling thread has used, s.
double threadCpuSeconds();

/// The planner's per-phase wall times as (name, seconds), in a fixed order.
std::vector<std::pair<std::string, double>> phaseList(const PhaseTimes& times);

}  // namespace parksim::bench
