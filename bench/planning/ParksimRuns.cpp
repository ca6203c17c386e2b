#include "bench/planning/ParksimRuns.h"
#include "bench/planning/PlanShape.h"
#include "parksim/core/io/NumberFormat.h"

#include <time.h>

#include <climits>
#include <cstdio>

namespace parksim::bench {

double threadCpuSeconds() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

std::string budgetName(const SearchDef& planner) {
  std::string name;
  // INT_MAX iterations is how a purely time-budgeted run is asked for: leave it out.
  if (planner.max_iterations < INT_MAX) {
    name = "iterations=" + std::to_string(planner.max_iterations);
  }
  if (planner.max_time_s > 0.0) {
    if (!name.empty()) name += '+';
    name += "time=" + formatGeneral(planner.max_time_s) + "s";
  }
  return name;
}

std::vector<std::pair<std::string, double>> phaseList(const PhaseTimes& t) {
  std::vector<std::pair<std::string, double>> phases;
  for (const auto& [name, s] : phaseTimeList(t)) phases.emplace_back(name, s);
  phases.emplace_back("total", t.total_s);
  return phases;
}

BenchRecord runParksim(const Scenario& scenario, const BulletCollisionWorld& world,
                       const ParksimRunDef& def) {
  const double cpu0 = threadCpuSeconds();
  const PlanResult result = planScenario(scenario, world, def.setup, {}, *def.planners);
  const double cpu = threadCpuSeconds() - cpu0;
  // As planned: the planner and steering for the world's drive, the budget for its lot.
  const PlanSetup planned = resolvedPlanSetup(def.setup, scenario, *def.planners);
  BenchRecord r;
  r.library = "parksim";
  r.planner = planned.planner;
  if (def.setup.search.smooth) r.planner += "+smooth";
  // The A* planners drive their own motion primitives and analytic curves, whatever the
  // steering.
  if (planned.planner == "hybrid-a-star") {
    r.space = "primitives+reeds-shepp";
  } else if (planned.planner == "time-a-star") {
    r.space = "primitives+balkcom-mason";
  } else if (planned.planner == "car-a-star") {
    r.space = "car-primitives+reeds-shepp";
  } else {
    r.space = toString(planned.steering_kind);
  }
  r.scenario = scenario.name;
  r.seed = def.setup.search.seed;
  r.budget = budgetName(planned.search);
  r.solved = result.solved();
  r.status = toString(result.status);
  r.time_total_s = result.stats.times.total_s;
  r.cpu_total_s = cpu;
  r.iterations = result.stats.iterations;
  r.iterations_first = result.stats.first_solution_iteration;
  r.tree_size = static_cast<long>(result.stats.tree_size) + result.stats.goal_tree_size;
  r.collision_queries = result.stats.collision_queries;
  r.phases_s = phaseList(result.stats.times);
  if (result.solved()) {
    r.time_first_s = result.stats.first_solution_s;
    const PathCheck check =
        checkPath(densify(result.trajectory, scenario.robot, def.check.max_step_m), scenario, world,
                  def.check);
    r.valid = check.valid;
    r.min_clearance_m = check.min_clearance_m;
    r.length_m = result.trajectory.pathLength(scenario.robot);
    r.cusps = result.trajectory.cusps(scenario.robot);
    r.duration_s = result.trajectory.duration();
    r.duration_lower_bound_s = result.duration_lower_bound_s;
    r.free_space_bound_s = result.free_space_bound_s;
    r.steering_reversals_per_m = planShape(result.trajectory, scenario.robot).reversals_per_m;
    r.cost = result.cost;
  }
  return r;
}

}  // namespace parksim::bench
