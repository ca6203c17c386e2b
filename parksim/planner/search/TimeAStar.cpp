#include "parksim/planner/search/TimeAStar.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <random>
#include <string>

#include "parksim/core/io/Error.h"
#include "parksim/planner/motion/MotionPrimitives.h"
#include "parksim/planner/search/FootprintFit.h"
#include "parksim/planner/search/TimeAStarSearch.h"

namespace parksim {

namespace {

using Clock = std::chrono::steady_clock;
using detail::TimeSearchOutcome;

// Below this a duration difference is rounding, not an improvement, s.
constexpr double kImprovementS = 1e-9;

double seconds(Clock::time_point since) {
  return std::chrono::duration<double>(Clock::now() - since).count();
}

// One call of TimeAStar::solve: the searches, smoothing and the best plan so far.
class Solve {
 public:
  Solve(const RobotDef& robot, const LotBounds& lot, const MotionValidator& validator,
        const SearchDef& def, const TimeAStarDef& search, const TimingLimits& limits,
        const PathSmootherDef& smoothing, const std::vector<Obstacle>* obstacles,
        const PlanProgress& progress)
      : robot_(robot),
        lot_(lot),
        validator_(validator),
        def_(def),
        search_(search),
        limits_(limits),
        smoother_(robot, validator, limits, smoothing),
        progress_(progress),
        rng_(def.seed),
        t_begin_(Clock::now()) {
    if (obstacles) {
      fit_ = std::make_unique<FootprintFit>(*obstacles, robot, 0.5 * validator.def().resolution_m);
    }
  }

  PlanResult run(const Pose2& start, const GoalRegion& goal);

 private:
  PlanResult finish(PlanStatus status, std::string message);
  TimeSearchOutcome search(const Pose2& start, const Pose2& goal, const std::vector<Pose2>& roots,
                           double weight);
  void offer(const Pose2& start, std::vector<PathPiece> pieces);

  const RobotDef& robot_;
  const LotBounds& lot_;
  const MotionValidator& validator_;
  const SearchDef& def_;
  const TimeAStarDef& search_;
  TimingLimits limits_;
  PathSmoother smoother_;
  const PlanProgress& progress_;
  std::mt19937_64 rng_;
  std::unique_ptr<FootprintFit> fit_;
  Clock::time_point t_begin_;
  long queries_before_ = 0;
  double margin_m_ = 0.0;

  std::vector<PathPiece> best_;                              // driven from the start
  std::vector<PathPiece> first_found_;                       // the first search's path, as found
  double best_s_ = std::numeric_limits<double>::infinity();  // best_'s duration
  // best_ holds a path (it is empty when the start already is the goal pose).
  bool found() const { return best_s_ < std::numeric_limits<double>::infinity(); }
  PlanResult result_;
};

PlanResult Solve::finish(PlanStatus status, std::string message) {
  result_.status = status;
  result_.message = std::move(message);
  result_.objective = PlanObjective::kDuration;
  result_.stats.collision_queries = validator_.queries() - queries_before_;
  result_.stats.times.total_s = seconds(t_begin_);
  return std::move(result_);
}

// One weighted search, in windows growing until one holds a path or the window is the lot.
TimeSearchOutcome Solve::search(const Pose2& start, const Pose2& goal,
                                const std::vector<Pose2>& roots, double weight) {
  detail::TimeSearchConfig config;
  config.robot = robot_;
  config.validator = &validator_;
  config.fit = fit_.get();
  config.def = &search_;
  config.limits = limits_;
  config.weight = weight;
  config.max_expansions = def_.max_iterations;
  if (def_.max_time_s > 0.0) {
    config.deadline = t_begin_ + std::chrono::duration_cast<Clock::duration>(
                                     std::chrono::duration<double>(def_.max_time_s));
  }
  config.cancel = def_.cancel;
  config.progress = &progress_;
  config.progress_budget = def_.max_iterations;
  const bool backward = search_.from_goal;
  const std::vector<Pose2> sources = backward ? roots : std::vector<Pose2>{start};
  const std::vector<Pose2> targets = backward ? std::vector<Pose2>{start} : roots;
  return detail::searchWidening(config, lot_, start, goal, margin_m_, result_.stats, [&] {
    return detail::runTimeSearch(config, sources, targets, backward);
  });
}

// Smooths a path found and keeps it when it is the fastest so far.
void Solve::offer(const Pose2& start, std::vector<PathPiece> pieces) {
  if (first_found_.empty()) first_found_ = pieces;
  if (def_.smooth) {
    const Clock::time_point t0 = Clock::now();
    PathSmoothingStats s;
    pieces = smoother_.smooth(start, std::move(pieces), def_.smoothing_attempts, rng_, &s);
    result_.stats.smoothing_shortcuts += s.shortcuts;
    result_.stats.smoothing_fillets += s.fillets;
    result_.stats.times.smoothing_s += seconds(t0);
  }
  const double d = timedDuration(pieces, limits_);
  if (!(d < best_s_ - kImprovementS)) return;
  best_ = std::move(pieces);
  best_s_ = d;
  if (result_.stats.first_solution_s < 0.0) {
    result_.stats.first_solution_s = seconds(t_begin_);
    result_.stats.first_solution_iteration = result_.stats.iterations;
  }
  result_.cost_history.push_back({seconds(t_begin_), result_.stats.iterations, d});
}

PlanResult Solve::run(const Pose2& start, const GoalRegion& goal) {
  queries_before_ = validator_.queries();
  if (!validator_.isValid(start)) {
    return finish(PlanStatus::kInvalidStart,
                  validator_.insideLot(start)
                      ? "start pose collides"
                      : "start pose lies within half the motion-check resolution of the lot edge");
  }
  std::vector<Pose2> roots;
  for (const Pose2& g : {goal.pose, Pose2{goal.pose.x, goal.pose.y, goal.pose.theta + kPi}}) {
    if (validator_.isValid(g)) roots.push_back(g);
    if (!goal.either_heading) break;
  }
  if (roots.empty()) {
    return finish(PlanStatus::kInvalidGoal,
                  validator_.insideLot(goal.pose)
                      ? "goal pose collides"
                      : "goal pose lies within half the motion-check resolution of the lot edge");
  }
  margin_m_ = firstMargin(search_.window, start, goal.pose);
  const bool anytime = def_.max_time_s > 0.0;
  double weight = search_.heuristic_weight;
  TimeSearchOutcome::Status last = TimeSearchOutcome::Status::kExhausted;
  while (true) {
    TimeSearchOutcome out = search(start, goal.pose, roots, weight);
    last = out.status;
    if (out.status == TimeSearchOutcome::Status::kFound) offer(start, std::move(out.pieces));
    if (!anytime || out.status == TimeSearchOutcome::Status::kTimeLimit ||
        seconds(t_begin_) > def_.max_time_s) {
      break;
    }
    if (weight > 1.0) {
      weight = std::max(1.0, weight - search_.anytime_weight_step);
      continue;
    }
    // Every weight searched: spend what is left on fresh random shortcuts of the best plan.
    while (found() && def_.smooth && seconds(t_begin_) < def_.max_time_s) offer(start, best_);
    break;
  }
  if (!found()) {
    if (def_.cancelled()) {
      return finish(PlanStatus::kCancelled,
                    "cancelled before a collision-free trajectory to "
                    "the goal was found");
    }
    if (last == TimeSearchOutcome::Status::kTimeLimit) {
      return finish(PlanStatus::kTimeLimit, "no collision-free trajectory to the goal within " +
                                                std::to_string(def_.max_time_s) + " s");
    }
    return finish(PlanStatus::kIterationLimit,
                  last == TimeSearchOutcome::Status::kExhausted
                      ? "no collision-free trajectory to the goal: every reachable cell was "
                        "expanded"
                      : "no collision-free trajectory to the goal within " +
                            std::to_string(def_.max_iterations) + " expansions");
  }
  Trajectory traj = timePieces(start, best_, robot_, limits_);
  if (!validator_.isValid(traj)) {
    // Only rounding can make a path of validated stretches fail as a whole: fall back to the
    // path as the search found it.
    best_ = first_found_;
    traj = timePieces(start, best_, robot_, limits_);
    result_.cost_history.push_back({seconds(t_begin_), result_.stats.iterations, 0.0});
    if (!validator_.isValid(traj)) {
      return finish(PlanStatus::kIterationLimit,
                    "the joined plan failed its whole-path check (rounding); no plan");
    }
  }
  result_.cost = traj.duration();
  result_.cost_history.back().cost = result_.cost;
  result_.trajectory = std::move(traj);
  result_.waypoints.push_back(start);
  Pose2 pose = start;
  for (const PathPiece& p : best_) {
    pose = geometryOf(pose, {p}, robot_).points.back().pose;
    result_.waypoints.push_back(pose);
  }
  result_.waypoints.back() = result_.trajectory.points.back().pose;
  return finish(PlanStatus::kSolved, "solved");
}

}  // namespace

TimeAStar::TimeAStar(const RobotDef& robot, const LotBounds& lot, const MotionValidator& validator,
                     const SearchDef& def, const TimeAStarDef& search, const TimingLimits& limits,
                     const PathSmootherDef& smoothing, const std::vector<Obstacle>* obstacles)
    : robot_(robot),
      lot_(lot),
      validator_(validator),
      def_(def),
      search_(search),
      limits_(limits),
      smoothing_(smoothing),
      obstacles_(obstacles) {
  if (def.max_iterations < 0) throw Error("planner: max_iterations must be >= 0");
  if (!(def.max_time_s >= 0.0)) throw Error("planner: max_time_s must be >= 0");
  const TimeAStarDef& s = search;
  bool radii_ok = true;
  for (double r : s.arc_radii_m) radii_ok = radii_ok && r > 0.0;
  for (double a : s.spin_angles_rad) radii_ok = radii_ok && a > 0.0;
  for (double a : s.fine_spin_angles_rad) radii_ok = radii_ok && a > 0.0;
  if (!(s.cell_m >= 0.0) || !(s.step_m >= 0.0) || s.heading_bins < 4 || !radii_ok ||
      !(s.fine_cell_m > 0.0) || s.fine_heading_bins < 4 || !(s.fine_step_m > 0.0) ||
      s.analytic_interval < 1 || !(s.heuristic_weight >= 1.0) || !(s.anytime_weight_step > 0.0) ||
      s.max_heuristic_cells_per_side < 1 || !(s.window.min_margin_m > 0.0) ||
      !(s.window.margin_fraction >= 0.0)) {
    throw Error(
        "time-a-star: cell and step must be >= 0, heading_bins >= 4, radii and turns > 0, "
        "analytic_interval >= 1, heuristic_weight >= 1, window margin > 0");
  }
}

PlanResult TimeAStar::solve(const Pose2& start, const GoalRegion& goal,
                            const PlanProgress& progress) const {
  return Solve(robot_, lot_, validator_, def_, search_, limits_, smoothing_, obstacles_, progress)
      .run(start, goal);
}

}  // namespace parksim
