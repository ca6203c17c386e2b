#include "parksim/results/episode/PlanFile.h"

#include <algorithm>
#include <filesystem>

#include "parksim/core/geometry/Angle.h"
#include "parksim/core/io/AtomicFile.h"
#include "parksim/planner/base/FreeSpaceBound.h"
#include "parksim/results/episode/JsonFile.h"
#include "parksim/results/episode/TrajectoryFile.h"

namespace parksim {

namespace {

// When a car's plan changes gear: the times of its first row moving the other way, s.
nlohmann::json cuspTimes(const RobotDef& car, const Trajectory& plan) {
  nlohmann::json times = nlohmann::json::array();
  const double still = kCarStillFraction * car.max_speed_mps;
  int gear = 0;
  for (std::size_t i = 0; i + 1 < plan.points.size(); ++i) {
    const double v = toTwist(plan.points[i].wheels, car).v_mps;
    const int g = v > still ? 1 : (v < -still ? -1 : 0);
    if (g == 0) continue;
    if (gear != 0 && g != gear) times.push_back(plan.points[i].t_s);
    gear = g;
  }
  return times;
}

// A car's gear changes (`cusps` counts them), whoever made the plan: when they are.
void addCarKeys(const Scenario& scenario, const Trajectory& plan, nlohmann::json& j) {
  j["cusp_times_s"] = cuspTimes(scenario.robot, plan);
}

// The keys of what was asked: the world, the planner and its settings, the build.
nlohmann::json setupKeys(const Scenario& scenario, const PlanSetup& setup) {
  return {
      {"provenance", provenanceToJson(buildProvenance())},
      {"world", scenario.source_path},
      {"scenario", scenario.name},
      {"planner", setup.planner},
      {"planner_params", setup.planner_params},
      {"steering", toString(setup.steering_kind)},
      {"smooth", setup.search.smooth},
      {"seed", setup.search.seed},
      {"max_iterations", setup.search.max_iterations},
      {"time_limit_s", setup.search.max_time_s},
      {"motion_check_resolution_m", setup.validation.resolution_m},
      {"timing", toString(setup.timing)},
      {"feedback_headroom", setup.feedback_headroom},
  };
}

}  // namespace

nlohmann::json planSummary(const Scenario& scenario, const PlanSetup& setup,
                           const PlanResult& result) {
  const PhaseTimes& t = result.stats.times;
  nlohmann::json j = setupKeys(scenario, setup);
  j.update({
      {"status", toString(result.status)},
      {"solved", result.solved()},
      {"message", result.message},
      {"iterations", result.stats.iterations},
      {"tree_size", result.stats.tree_size},
      {"goal_tree_size", result.stats.goal_tree_size},
      {"goal_attempts", result.stats.goal_attempts},
      {"connection_attempts", result.stats.connection_attempts},
      {"rewires", result.stats.rewires},
      {"smoothing_shortcuts", result.stats.smoothing_shortcuts},
      {"collision_queries", result.stats.collision_queries},
      {"planning_time_s", t.total_s},
  });
  nlohmann::json phases = nlohmann::json::object();
  for (const auto& [name, s] : phaseTimeList(t)) phases[name] = s;
  j["phase_times_s"] = phases;
  if (result.stats.first_solution_iteration >= 0) {
    j["first_solution_s"] = result.stats.first_solution_s;
    j["first_solution_iteration"] = result.stats.first_solution_iteration;
  }
  // A planner's cost is a path cost in metres, or for planners that minimise it the plan's
  // duration in seconds: the key carries the unit.
  const char* const cost_key = result.objective == PlanObjective::kDuration ? "cost_s" : "cost_m";
  j["objective"] = toString(result.objective);
  nlohmann::json history = nlohmann::json::array();
  for (const CostSample& c : result.cost_history) {
    history.push_back({{"time_s", c.time_s}, {"iteration", c.iteration}, {cost_key, c.cost}});
  }
  j["cost_history"] = history;
  if (result.solved()) {
    const Pose2& end = result.trajectory.points.back().pose;
    j[cost_key] = result.cost;
    j["path_length_m"] = result.trajectory.pathLength(scenario.robot);
    j["duration_s"] = result.trajectory.duration();
    j["duration_lower_bound_s"] = result.duration_lower_bound_s;
    j["duration_over_lower_bound"] =
        result.duration_lower_bound_s > 0.0
            ? result.trajectory.duration() / result.duration_lower_bound_s
            : 0.0;
    j["free_space_bound_s"] = result.free_space_bound_s;
    j["duration_over_free_space_bound"] =
        result.free_space_bound_s > 0.0 ? result.trajectory.duration() / result.free_space_bound_s
                                        : 0.0;
    j["cusps"] = result.trajectory.cusps(scenario.robot);
    if (scenario.robot.isCar()) addCarKeys(scenario, result.trajectory, j);
    j["waypoints"] = result.waypoints.size();
    j["final_pos_err_m"] = positionDistance(end, scenario.goal.pose);
    j["final_heading_err_deg"] = radToDeg(headingDistance(end, scenario.goal.pose));
  }
  return j;
}

nlohmann::json trajectorySummary(const Scenario& scenario, const Trajectory& plan) {
  const Pose2& end = plan.points.back().pose;
  nlohmann::json j = {
      {"path_length_m", plan.pathLength(scenario.robot)},
      {"duration_s", plan.duration()},
      {"cusps", plan.cusps(scenario.robot)},
      {"final_pos_err_m", positionDistance(end, scenario.goal.pose)},
      {"final_heading_err_deg", radToDeg(headingDistance(end, scenario.goal.pose))},
  };
  if (scenario.robot.isCar()) {
    addCarKeys(scenario, plan, j);
    // In rows as far apart as the plan's farthest: longer rows only lower the bound.
    double period = 0.0;
    for (std::size_t i = 0; i + 1 < plan.points.size(); ++i) {
      period = std::max(period, plan.points[i + 1].t_s - plan.points[i].t_s);
    }
    if (period > 0.0) {
      TimingLimits limits;
      limits.period_s = period;
      const double bound = scenarioFreeSpaceBound(scenario, limits);
      j["free_space_bound_s"] = bound;
      j["duration_over_free_space_bound"] = bound > 0.0 ? plan.duration() / bound : 0.0;
    }
  }
  return j;
}

nlohmann::json failedPlanSummary(const Scenario& scenario, const PlanSetup& setup,
                                 const std::string& status, const std::string& message) {
  nlohmann::json j = setupKeys(scenario, setup);
  j["status"] = status;
  j["solved"] = false;
  j["message"] = message;
  return j;
}

void writePlanFiles(const std::string& dir, const Scenario& scenario, const Trajectory* plan,
                    const nlohmann::json& summary) {
  ensureDirectory(dir);
  const std::string traj_path = dir + "/trajectory.csv";
  if (plan != nullptr) {
    writeTrajectoryCsv(traj_path, *plan, scenario.robot);
  } else {
    // Never leave an earlier run's trajectory beside this run's plan.json.
    std::error_code ec;
    std::filesystem::remove(traj_path, ec);
  }
  writeFileAtomically(dir + "/plan.json", jsonText(summary));
}

void addPlanKeys(nlohmann::json& metrics, const nlohmann::json& summary) {
  for (const auto& [key, value] : summary.items()) {
    if (value.is_array() || key == "provenance") continue;
    if (value.is_object()) {
      for (const auto& [sub, inner] : value.items()) metrics["plan_" + key + "." + sub] = inner;
    } else {
      metrics["plan_" + key] = value;
    }
  }
}

}  // namespace parksim
