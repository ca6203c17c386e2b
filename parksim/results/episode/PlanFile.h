#pragma once
// plan.json (a plan's status, settings and statistics) beside trajectory.csv, and the plan
// keys metrics.json repeats with a plan_ prefix.

#include <string>

#include <nlohmann/json.hpp>

#include "parksim/core/model/Scenario.h"
#include "parksim/core/model/Trajectory.h"
#include "parksim/planner/base/PlanResult.h"
#include "parksim/planner/base/PlanScenario.h"

namespace parksim {

/// plan.json's content: status, planner, steering, seed, iterations, tree sizes, per-phase
/// times, planning_time_s, first solution, cost and its history, path_length_m, cusps, final
/// pose error; for a car also cusp_times_s (when it changes gear). (The episode pipeline adds planner_origin for a
/// planner that is not parksim's own: usercode/Components.h's plannerOrigin.)
nlohmann::json planSummary(const Scenario& scenario, const PlanSetup& setup,
                           const PlanResult& result);

/// plan.json's content when the planner gave no result (planner_error): planSummary's keys of
/// the setup (planner, planner_params, steering, seed, budget, ...), `status`, `message`, and
/// solved false.
nlohmann::json failedPlanSummary(const Scenario& scenario, const PlanSetup& setup,
                                 const std::string& status, const std::string& message);

/// The statistics a trajectory carries by itself, for a plan the planner did not make (a plan
/// file, a Python array): path_length_m, duration_s, cusps, final pose error; for a car also
/// cusp_times_s and its free-space bound (planner/FreeSpaceBound.h: free_space_bound_s, in rows
/// as far apart as the plan's farthest, and duration_over_free_space_bound).
nlohmann::json trajectorySummary(const Scenario& scenario, const Trajectory& plan);

/// Adds planSummary's keys to a flat metrics.json with a plan_ prefix: nested objects flattened
/// as plan_<key>.<sub>; arrays (the RRT* cost history) and provenance stay in plan.json.
void addPlanKeys(nlohmann::json& metrics, const nlohmann::json& summary);

/// Writes DIR/plan.json (`summary`: planSummary's or failedPlanSummary's) and DIR/trajectory.csv
/// when `plan` is given (a plan that may be driven; otherwise an earlier one is removed),
/// creating DIR.
void writePlanFiles(const std::string& dir, const Scenario& scenario, const Trajectory* plan,
                    const nlohmann::json& summary);

}  // namespace parksim
