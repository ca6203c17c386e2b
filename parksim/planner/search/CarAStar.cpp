#include "parksim/planner/search/CarAStar.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <queue>
#include <string>
#include <unordered_map>

#include "parksim/core/io/Error.h"
#include "parksim/core/model/Geometry.h"
#include "parksim/planner/motion/CarPlanAlong.h"
#include "parksim/planner/motion/CarTimeCost.h"
#include "parksim/planner/motion/MotionPrimitives.h"
#include "parksim/planner/search/CellSearch.h"
#include "parksim/planner/search/FootprintFit.h"
#include "parksim/planner/steering/ReedsSheppSteering.h"

namespace parksim {

namespace {

using detail::CellSearchConfig;
using detail::CellSearchOutcome;
using detail::secondsSince;
using CarClock = detail::SearchClock;

// The car in the cell search (CellSearch.h): arcs of a few curvatures up to its tightest and
// straights, forward and reverse; junctions priced by CarTimeCost; Reeds-Shepp lengths and
// curves at its tightest radius.
class CarModel {
 public:
  // A move, its curvature and what it costs to drive, precomputed.
  struct Move {
    MotionPrimitive primitive;
    PathPiece piece;  // in the search's direction
    double kappa = 0.0;
    double time_s = 0.0;
  };
  // The move into a node: its gear (0 at the sources) and curvature.
  struct Arrival {
    int direction = 0;
    double kappa = 0.0;
  };

  CarModel(const RobotDef& car, const CarAStarDef& def, const CarTimeCost& cost,
           const ReedsSheppSteering& curves, const std::vector<Pose2>& targets)
      : car_(car), def_(def), cost_(cost), curves_(curves), targets_(targets) {
    const double radius = footprintRadius(car);
    cell_ = def_.cell_m > 0.0 ? def_.cell_m : 0.125 * radius;
    step_ = def_.step_m > 0.0 ? def_.step_m : 1.5 * cell_;
    speed_ = cost.limits().max_speed_mps;
    coarse_ = movesOf(step_);
    fine_zone_m_ = def_.fine_zone_m < 0.0 ? 2.0 * radius : def_.fine_zone_m;
  }

  const RobotDef& robot() const { return car_; }

  detail::CellSearchLayout layout(const LotBounds& window) const {
    const double longer =
        std::max(window.x_max_m - window.x_min_m, window.y_max_m - window.y_min_m);
    const double grid_cell =
        std::max(def_.heuristic_cell_m > 0.0 ? def_.heuristic_cell_m : 2.0 * cell_,
                 longer / def_.max_heuristic_cells_per_side);
    return {{cell_, def_.heading_bins},
            fine_zone_m_,
            grid_cell,
            def_.analytic_near_s,
            def_.analytic_interval};
  }

  // Level 1, 2, ...: cells and moves fine_scale^level times as large, heading bins as many
  // times more.
  CellSize fineLevel(int level) {
    const double scale = std::pow(def_.fine_scale, level);
    fine_ = movesOf(scale * step_);
    return {scale * cell_, static_cast<int>(std::lround(def_.heading_bins / scale))};
  }

  const std::vector<Move>& moves(bool fine) const { return fine ? fine_ : coarse_; }

  // The sources are where the search starts: no junction there.
  double junction(const Arrival& from, const Move& move) const {
    return from.direction == 0
               ? 0.0
               : cost_.junctionTime(from.direction, from.kappa, move.primitive.direction,
                                    move.kappa, 0.5 * move.primitive.length_m);
  }
  Arrival arrival(const Move& move) const { return {move.primitive.direction, move.kappa}; }

  // Seconds to the nearest target at the speed limit: the larger of the Reeds-Shepp length and
  // the grid distance.
  double heuristic(const Pose2& p, double grid) const {
    double curve = std::numeric_limits<double>::infinity();
    for (const Pose2& t : targets_) curve = std::min(curve, curves_.distance(p, t));
    return std::max(curve, grid) / speed_;
  }
  double gridHeuristic(double grid) const { return grid / speed_; }

  std::vector<PathPiece> curve(const Pose2& from, const Pose2& target) const {
    return curves_.pieces(from, target);
  }

 private:
  std::vector<Move> movesOf(double step) const {
    const double kappa_max = car_.maxCurvature();
    std::vector<double> radii;
    for (int j = 1; j <= def_.curvature_steps; ++j) {
      radii.push_back(1.0 / (kappa_max * j / def_.curvature_steps));
    }
    std::vector<Move> moves;
    for (const MotionPrimitive& p : makePrimitives(step, radii, std::vector<double>{})) {
      const double kappa = p.motion.omega_radps / p.motion.v_mps;
      moves.push_back({p, pieceOf(p, car_), kappa, cost_.pieceTime(p.length_m, kappa)});
    }
    return moves;
  }

  const RobotDef& car_;
  const CarAStarDef& def_;
  const CarTimeCost& cost_;
  const ReedsSheppSteering& curves_;
  std::vector<Pose2> targets_;
  double cell_ = 0.0;
  double step_ = 0.0;
  double speed_ = 0.0;
  double fine_zone_m_ = 0.0;
  std::vector<Move> coarse_;
  std::vector<Move> fine_;
};

}  // namespace

CarAStar::CarAStar(const RobotDef& car, const LotBounds& lot, const MotionValidator& validator,
                   const SearchDef& def, const CarAStarDef& search, const CarLimits& limits,
                   const std::vector<Obstacle>* obstacles)
    : car_(car),
      lot_(lot),
      validator_(validator),
      def_(def),
      search_(search),
      limits_(limits),
      obstacles_(obstacles) {
  if (!car.isCar()) throw Error("car-a-star: the robot is not a car (robot.drive: car)");
  if (def.max_iterations < 0) throw Error("planner: max_iterations must be >= 0");
  if (!(def.max_time_s >= 0.0)) throw Error("planner: max_time_s must be >= 0");
  const CarAStarDef& s = search;
  if (!(s.cell_m >= 0.0) || !(s.step_m >= 0.0) || !(s.heuristic_cell_m >= 0.0) ||
      s.heading_bins < 4 || s.curvature_steps < 1 || !(s.heuristic_weight >= 1.0) ||
      !(s.gear_change_penalty_s >= 0.0) || s.analytic_interval < 1 ||
      !(s.fine_scale > 0.0 && s.fine_scale < 1.0) || s.max_heuristic_cells_per_side < 1 ||
      !(s.window.min_margin_m > 0.0) || !(s.window.margin_fraction >= 0.0)) {
    throw Error(
        "car-a-star: cell and step must be >= 0, heading_bins >= 4, curvature_steps >= 1, "
        "heuristic_weight >= 1, penalty >= 0, analytic_interval >= 1, fine_scale in (0, 1), "
        "window margin > 0");
  }
}

PlanResult CarAStar::solve(const Pose2& start, const GoalRegion& goal,
                           const PlanProgress& progress) const {
  const CarClock::time_point t_begin = CarClock::now();
  const long queries_before = validator_.queries();
  PlanResult result;
  result.objective = PlanObjective::kDuration;
  auto finish = [&](PlanStatus status, std::string message) {
    result.status = status;
    result.message = std::move(message);
    result.stats.collision_queries = validator_.queries() - queries_before;
    result.stats.times.total_s = secondsSince(t_begin);
    return std::move(result);
  };
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
  std::unique_ptr<FootprintFit> fit;
  if (obstacles_) {
    fit = std::make_unique<FootprintFit>(*obstacles_, car_, 0.5 * validator_.def().resolution_m);
  }
  const ReedsSheppSteering curves(car_);  // at the car's tightest radius
  const CarTimeCost cost(car_, limits_, search_.gear_change_penalty_s);
  CellSearchConfig config;
  config.validator = &validator_;
  config.fit = fit.get();
  config.weight = search_.heuristic_weight;
  if (def_.max_time_s > 0.0) {
    config.deadline = t_begin + std::chrono::duration_cast<CarClock::duration>(
                                    std::chrono::duration<double>(def_.max_time_s));
  }
  config.cancel = def_.cancel;
  config.progress = &progress;
  config.progress_budget = def_.max_iterations;
  const bool backward = search_.from_goal;
  const std::vector<Pose2> sources = backward ? roots : std::vector<Pose2>{start};
  const std::vector<Pose2> targets = backward ? std::vector<Pose2>{start} : roots;
  double margin = firstMargin(search_.window, start, goal.pose);
  PlanStats& st = result.stats;
  const CellSearchOutcome out =
      detail::searchWidening(config, lot_, start, goal.pose, margin, st, [&] {
        config.max_expansions = def_.max_iterations - st.iterations;
        CarModel model(car_, search_, cost, curves, targets);
        return detail::runCellSearch(config, model, sources, targets, backward);
      });
  st.goal_tree_size = static_cast<int>(roots.size());
  if (out.status != CellSearchOutcome::Status::kFound) {
    if (def_.cancelled()) {
      return finish(PlanStatus::kCancelled,
                    "cancelled before a collision-free trajectory to the goal was found");
    }
    if (out.status == CellSearchOutcome::Status::kTimeLimit) {
      return finish(PlanStatus::kTimeLimit, "no collision-free trajectory to the goal within " +
                                                std::to_string(def_.max_time_s) + " s");
    }
    return finish(PlanStatus::kIterationLimit,
                  out.status == CellSearchOutcome::Status::kExhausted
                      ? "no collision-free trajectory to the goal: every reachable cell was "
                        "expanded"
                      : "no collision-free trajectory to the goal within " +
                            std::to_string(def_.max_iterations) + " expansions");
  }
  // The pieces as the validator checks them: timed at the wheels' limits.
  const TimingLimits wheels{car_.max_wheel_speed_radps, car_.max_wheel_accel_radps2, 0.1};
  Trajectory traj = timePieces(start, out.pieces, car_, wheels);
  if (!validator_.isValid(traj)) {
    return finish(PlanStatus::kIterationLimit,
                  "the joined plan failed its whole-path check (rounding); no plan");
  }
  result.cost = carPlanDuration(out.pieces, car_, limits_);
  result.trajectory = std::move(traj);
  result.waypoints = {start, result.trajectory.points.back().pose};
  st.first_solution_s = secondsSince(t_begin);
  st.first_solution_iteration = st.iterations;
  result.cost_history.push_back({st.first_solution_s, st.iterations, result.cost});
  return finish(PlanStatus::kSolved, "solved");
}

}  // namespace parksim
