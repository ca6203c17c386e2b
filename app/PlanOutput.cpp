#include "app/PlanOutput.h"

#include <cmath>
#include <cstdio>
#include <filesystem>

#include "app/OptionChecks.h"
#include "app/Validators.h"
#include "parksim/core/AtomicFile.h"
#include "parksim/core/Error.h"
#include "parksim/core/Provenance.h"
#include "parksim/sim/EpisodeFiles.h"

namespace parksim::app {

namespace {

template <class Kind>
std::string namesOf(const std::vector<Kind>& kinds) {
  std::string names;
  for (Kind k : kinds) names += (names.empty() ? "" : ", ") + std::string(toString(k));
  return names;
}

}  // namespace

void PlanCliOptions::addTo(CLI::App& sub) {
  sub.add_option("--planner", planner, "one of: " + namesOf(allPlannerKinds()))
      ->capture_default_str();
  sub.add_option("--steering", steering,
                 "steering function, one of: " + namesOf(allSteeringKinds()))
      ->capture_default_str();
  // CLI11 would wrap "-3" and clamp 2^64 into a 64-bit unsigned seed; refuse both instead.
  sub.add_option("--seed", seed, "seed of the planner's random number generator")
      ->capture_default_str()
      ->check(unsigned64());
  sub.add_option("--max-iterations", max_iterations,
                 "iteration budget (hybrid-a-star: node expansions); auto: 2000 for tree "
                 "planners, 20000 for hybrid-a-star, times max(1, lot area / 2.16 m^2)")
      ->capture_default_str();
  sub.add_option("--time-limit", time_limit_s,
                 "wall-time budget of the search, s (0: none); the plan then depends on the "
                 "machine's speed, so reproducible runs use --max-iterations alone")
      ->capture_default_str()
      ->check(realIn(0.0, 3600.0));
  sub.add_flag("--smooth", smooth, "shortcut-smooth the plan (study 3(c)(3))");
  sub.add_option("--smoothing-attempts", smoothing_attempts, "random shortcuts tried by --smooth")
      ->capture_default_str()
      ->check(integerIn(0, kMaxSmoothingAttempts));
  sub.add_option("--timing", timing,
                 "time-optimal: re-time the plan to the fastest wheel speeds within the limits "
                 "(less the feedback headroom); study: keep the steering controller's timing")
      ->capture_default_str()
      ->check(CLI::IsMember({"time-optimal", "study"}));
  sub.add_option("--feedback-headroom", feedback_headroom,
                 "share of the wheel-speed limit time-optimal plans leave to feedback, in [0, 1)")
      ->capture_default_str()
      ->check(realIn(0.0, 0.99));
  sub.add_option("--turning-radius", turning_radius_m,
                 "arc radius of reeds-shepp steering and of hybrid-a-star's primitives, m")
      ->capture_default_str()
      ->check(realIn(0.0, 100.0, true));
}

int parseIterationBudget(const std::string& text, PlannerKind kind, const LotBounds& lot,
                         const std::string& option) {
  if (text == "auto") return defaultIterationBudget(kind, lot);
  std::size_t used = 0;
  long value = -1;
  try {
    value = std::stol(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != text.size() || value < 0 || value > kMaxPlannerIterations) {
    throw Error(option + ": expected auto or an integer in [0, " +
                std::to_string(kMaxPlannerIterations) + "], got '" + text + "'");
  }
  return static_cast<int>(value);
}

PlanSetup PlanCliOptions::toSetup(const Scenario& scenario) const {
  PlanSetup setup;
  setup.planner.kind = plannerKindFromString(planner);
  setup.planner.seed = seed;
  setup.planner.max_iterations =
      parseIterationBudget(max_iterations, setup.planner.kind, scenario.lot);
  setup.planner.max_time_s = time_limit_s;
  setup.timing = timingKindFromString(timing);
  setup.feedback_headroom = feedback_headroom;
  setup.reeds_shepp.turning_radius_m = turning_radius_m;
  setup.planner.smooth = smooth;
  setup.planner.smoothing_attempts = smoothing_attempts;
  setup.steering_kind = steeringKindFromString(steering);
  return setup;
}

nlohmann::json planSummary(const Scenario& scenario, const PlanSetup& setup,
                           const PlanResult& result) {
  const PhaseTimes& t = result.stats.times;
  nlohmann::json j = {
      {"provenance", provenanceToJson(buildProvenance())},
      {"world", scenario.source_path},
      {"scenario", scenario.name},
      {"status", toString(result.status)},
      {"solved", result.solved()},
      {"message", result.message},
      {"planner", toString(setup.planner.kind)},
      {"steering", toString(setup.steering_kind)},
      {"smooth", setup.planner.smooth},
      {"seed", setup.planner.seed},
      {"max_iterations", setup.planner.max_iterations},
      {"time_limit_s", setup.planner.max_time_s},
      {"iterations", result.stats.iterations},
      {"tree_size", result.stats.tree_size},
      {"goal_tree_size", result.stats.goal_tree_size},
      {"goal_attempts", result.stats.goal_attempts},
      {"connection_attempts", result.stats.connection_attempts},
      {"rewires", result.stats.rewires},
      {"smoothing_shortcuts", result.stats.smoothing_shortcuts},
      {"collision_queries", result.stats.collision_queries},
      {"motion_check_resolution_m", setup.validation.resolution_m},
      {"planning_time_s", t.total_s},
      {"phase_times_s",
       {{"sampling", t.sampling_s},
        {"nearest_neighbour", t.nearest_s},
        {"steering", t.steering_s},
        {"collision_checking", t.collision_s},
        {"goal_checks", t.goal_check_s},
        {"rewiring", t.rewiring_s},
        {"connection", t.connection_s},
        {"smoothing", t.smoothing_s},
        {"heuristic", t.heuristic_s},
        {"timing", t.timing_s}}},
      {"timing", toString(setup.timing)},
      {"feedback_headroom", setup.feedback_headroom},
  };
  if (result.stats.first_solution_iteration >= 0) {
    j["first_solution_s"] = result.stats.first_solution_s;
    j["first_solution_iteration"] = result.stats.first_solution_iteration;
  }
  nlohmann::json history = nlohmann::json::array();
  for (const CostSample& c : result.cost_history) {
    history.push_back({{"time_s", c.time_s}, {"iteration", c.iteration}, {"cost_m", c.cost}});
  }
  j["cost_history"] = history;
  if (result.solved()) {
    const Pose2& end = result.trajectory.points.back().pose;
    j["cost_m"] = result.cost;
    j["path_length_m"] = result.trajectory.pathLength(scenario.robot);
    j["duration_s"] = result.trajectory.duration();
    j["duration_lower_bound_s"] = result.duration_lower_bound_s;
    j["duration_over_lower_bound"] =
        result.duration_lower_bound_s > 0.0
            ? result.trajectory.duration() / result.duration_lower_bound_s
            : 0.0;
    j["cusps"] = result.trajectory.cusps(scenario.robot);
    j["waypoints"] = result.waypoints.size();
    j["final_pos_err_m"] = positionDistance(end, scenario.goal.pose);
    j["final_heading_err_deg"] = radToDeg(headingDistance(end, scenario.goal.pose));
  }
  return j;
}

nlohmann::json trajectorySummary(const Scenario& scenario, const Trajectory& plan) {
  const Pose2& end = plan.points.back().pose;
  return {
      {"path_length_m", plan.pathLength(scenario.robot)},
      {"duration_s", plan.duration()},
      {"cusps", plan.cusps(scenario.robot)},
      {"final_pos_err_m", positionDistance(end, scenario.goal.pose)},
      {"final_heading_err_deg", radToDeg(headingDistance(end, scenario.goal.pose))},
  };
}

std::string jsonText(const nlohmann::json& j) {
  return j.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n";
}

void writePlanFiles(const std::string& dir, const Scenario& scenario, const PlanSetup& setup,
                    const PlanResult& result) {
  ensureDirectory(dir);
  const std::string traj_path = dir + "/trajectory.csv";
  if (result.solved()) {
    writeTrajectoryCsv(traj_path, result.trajectory, scenario.robot);
  } else {
    // Never leave an earlier run's trajectory beside this run's plan.json.
    std::error_code ec;
    std::filesystem::remove(traj_path, ec);
  }
  writeFileAtomically(dir + "/plan.json", jsonText(planSummary(scenario, setup, result)));
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

}  // namespace parksim::app
