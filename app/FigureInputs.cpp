#include "app/FigureInputs.h"

#include <cstdio>

#include "parksim/planner/MoveToPoseSteering.h"

namespace parksim::app {

std::string planCaption(const Scenario& scenario, const PlanSetup& setup,
                        const PlanResult& result) {
  char buf[256];
  if (result.solved()) {
    const int cusps = result.trajectory.cusps(scenario.robot);
    std::snprintf(buf, sizeof buf, "%s, %s (seed %llu): %d tree nodes, path %.2f m, %d cusp%s",
                  scenario.name.c_str(), toString(setup.planner.kind),
                  static_cast<unsigned long long>(setup.planner.seed), result.stats.tree_size,
                  result.trajectory.pathLength(scenario.robot), cusps, cusps == 1 ? "" : "s");
  } else {
    std::snprintf(buf, sizeof buf, "%s, %s (seed %llu): %s after %d iterations",
                  scenario.name.c_str(), toString(setup.planner.kind),
                  static_cast<unsigned long long>(setup.planner.seed), toString(result.status),
                  result.stats.iterations);
  }
  return buf;
}

PlanFigure planFigure(const Scenario& scenario, const PlanSetup& setup, const PlanResult& result) {
  return {toString(setup.planner.kind), planCaption(scenario, setup, result), result.trajectory,
          result.waypoints, result.tree_edges};
}

SteeringExample steeringExample(const Scenario& scenario, const std::optional<Pose2>& target) {
  SteeringExample example;
  example.start = scenario.start;
  example.target = target.value_or(Pose2{scenario.start.x + 0.3, scenario.start.y + 0.3, 0.0});
  const MoveToPoseSteering steer(scenario.robot);
  example.fixed_horizon =
      steer.steer(example.start, {}, example.target, SteerMode::kFixedHorizon).trajectory;
  example.to_goal = steer.steer(example.start, {}, example.target, SteerMode::kToGoal).trajectory;
  return example;
}

TrackingSeries trackingSeries(const std::vector<ExecutedRow>& rows) {
  TrackingSeries series;
  for (const ExecutedRow& row : rows) {
    series.t_s.push_back(row.t_s);
    series.position_error_m.push_back(row.pos_err_m);
    series.heading_error_rad.push_back(row.heading_err_rad);
  }
  return series;
}

}  // namespace parksim::app
