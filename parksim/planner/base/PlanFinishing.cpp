#include "parksim/planner/base/PlanFinishing.h"

#include <chrono>
#include <cmath>
#include <optional>
#include <random>
#include <vector>

#include "parksim/planner/base/PathSmoother.h"
#include "parksim/planner/base/PlanScenario.h"
#include "parksim/planner/motion/CarPlanAlong.h"
#include "parksim/planner/motion/PathCost.h"

namespace parksim {

namespace {

double secondsSince(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// Smooths the plan along its exact geometry (PathSmoother.h) and times it at `limits`; keeps the
// plan as it was unless the result validates as a whole.
void smoothPlan(const PlanningProblem& problem, const TimingLimits& limits, PlanResult& result) {
  const auto t0 = std::chrono::steady_clock::now();
  const MotionValidator& validator = problem.validator;
  const RobotDef& robot = problem.scenario.robot;
  const long before = validator.queries();
  const PathSmoother smoother(robot, validator, limits, problem.setup.smoothing);
  // Its own stream, seeded by the planner's seed: the planner's draws stay as they were.
  std::mt19937_64 rng(problem.search().seed ^ 0x5e1ec7edULL);
  PathSmoothingStats stats;
  const Pose2 start = result.trajectory.points.front().pose;
  const std::vector<PathPiece> pieces = smoother.smooth(
      start, pathPieces(result.trajectory), problem.search().smoothing_attempts, rng, &stats);
  Trajectory timed = timePieces(start, pieces, robot, limits);
  if (validator.isValid(timed)) {
    result.trajectory = std::move(timed);
    result.stats.smoothing_shortcuts += stats.shortcuts;
    result.stats.smoothing_fillets += stats.fillets;
  }
  result.stats.collision_queries += validator.queries() - before;
  result.stats.times.smoothing_s += secondsSince(t0);
  result.stats.times.total_s += secondsSince(t0);
}

// A car's plan: the path's pieces, smoothed as a car's when asked, made a car's plan along them
// (CarPlanAlong.h); the path as it was found when the smoothed one cannot be. No plan when
// neither can (the status says why).
void finishCarPlan(const PlanningProblem& problem, bool smooth_geometry, PlanResult& result) {
  const auto t0 = std::chrono::steady_clock::now();
  const RobotDef& car = problem.scenario.robot;
  const MotionValidator& validator = problem.validator;
  const long before = validator.queries();
  const CarLimits limits =
      carLimits(car, problem.setup.feedback_headroom, problem.setup.timing_period_s);
  const Pose2 start = result.trajectory.points.front().pose;
  const std::vector<PathPiece> found = pathPieces(result.trajectory);
  std::vector<PathPiece> pieces = found;
  if (smooth_geometry) {
    // Shortcuts keep the search's clearance (carSearchValidation).
    const std::unique_ptr<ClearanceValidator> clear = carSearchValidation(problem);
    const PathSmoother smoother(limits, car, clear->validator(), problem.setup.smoothing);
    std::mt19937_64 rng(problem.search().seed ^ 0x5e1ec7edULL);
    PathSmoothingStats stats;
    pieces = smoother.smooth(start, found, problem.search().smoothing_attempts, rng, &stats);
    result.stats.smoothing_shortcuts += stats.shortcuts;
    result.stats.collision_queries += clear->validator().queries();
    result.stats.times.smoothing_s += secondsSince(t0);
  }
  // The plan ends where the path does, to a tenth of the goal's tolerance.
  const double end_tolerance = 0.1 * problem.scenario.goal.position_tolerance_m;
  std::optional<Trajectory> plan =
      carPlanAlong(start, pieces, car, limits, validator, end_tolerance);
  if (!plan && smooth_geometry) {
    plan = carPlanAlong(start, found, car, limits, validator, end_tolerance);
  }
  result.stats.collision_queries += validator.queries() - before;
  if (!plan) {
    result.status = PlanStatus::kIterationLimit;
    result.message = "the path found could not be made a car's plan that validates";
    result.trajectory = {};
    result.cost = 0.0;
    result.cost_history.clear();
  } else {
    result.trajectory = std::move(*plan);
    const CostWeights w{problem.search().reverse_penalty, problem.search().cusp_penalty_m};
    result.cost = result.objective == PlanObjective::kDuration
                      ? result.trajectory.duration()
                      : trajectoryCost(result.trajectory, car, w);
    if (result.cost_history.empty()) {
      result.cost_history.push_back({result.stats.times.total_s, result.stats.iterations, 0.0});
    }
    result.cost_history.back().cost = result.cost;
    if (!result.waypoints.empty()) result.waypoints.back() = result.trajectory.points.back().pose;
  }
  result.stats.times.timing_s = secondsSince(t0) - result.stats.times.smoothing_s;
  result.stats.times.total_s += secondsSince(t0);
}

}  // namespace

std::unique_ptr<ClearanceValidator> carSearchValidation(const PlanningProblem& problem) {
  const Scenario& s = problem.scenario;
  if (!s.robot.isCar()) return nullptr;
  std::vector<Pose2> spared{s.start, s.goal.pose};
  if (s.goal.either_heading) {
    spared.push_back({s.goal.pose.x, s.goal.pose.y, s.goal.pose.theta + kPi});
  }
  return std::make_unique<ClearanceValidator>(problem.checker, s.robot, s.lot,
                                              problem.setup.validation, std::move(spared));
}

void finishPlan(const PlanningProblem& problem, bool smooth_geometry, PlanResult& result) {
  if (problem.scenario.robot.isCar()) {
    finishCarPlan(problem, smooth_geometry, result);
    return;
  }
  const RobotDef& robot = problem.scenario.robot;
  const bool time_optimal = problem.setup.timing == TimingKind::kTimeOptimal;
  if (smooth_geometry) {
    const TimingLimits own =
        time_optimal ? problem.limits
                     : TimingLimits{robot.max_wheel_speed_radps, robot.max_wheel_accel_radps2, 0.1};
    smoothPlan(problem, own, result);
  }
  const auto t0 = std::chrono::steady_clock::now();
  if (time_optimal) {
    const long before = problem.validator.queries();
    Trajectory timed = retime(result.trajectory, robot, problem.limits);
    if (problem.validator.isValid(timed)) result.trajectory = std::move(timed);
    result.stats.collision_queries += problem.validator.queries() - before;
  }
  const CostWeights w{problem.search().reverse_penalty, problem.search().cusp_penalty_m};
  result.cost = trajectoryCost(result.trajectory, robot, w);
  // Re-timing keeps the geometry (the cost moves by rounding only); smoothing changes it.
  if (!result.cost_history.empty() &&
      std::abs(result.cost - result.cost_history.back().cost) > 1e-9) {
    result.cost_history.push_back(
        {result.stats.times.total_s, result.stats.iterations, result.cost});
  } else if (!result.cost_history.empty()) {
    result.cost_history.back().cost = result.cost;
  }
  result.stats.times.timing_s = secondsSince(t0);
  result.stats.times.total_s += result.stats.times.timing_s;
}

}  // namespace parksim
