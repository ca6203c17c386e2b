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
#include "parksim/planner/search/FootprintFit.h"
#include "parksim/planner/search/ObstacleHeuristic.h"
#include "parksim/planner/search/SearchCells.h"
#include "parksim/planner/steering/ReedsSheppSteering.h"

namespace parksim {

namespace {

using CarClock = std::chrono::steady_clock;

double secondsSince(CarClock::time_point since) {
  return std::chrono::duration<double>(CarClock::now() - since).count();
}

// A move, its curvature and what it costs to drive, precomputed.
struct CarMove {
  MotionPrimitive primitive;
  PathPiece piece;  // in the search's direction
  double kappa = 0.0;
  double time_s = 0.0;
};

// What one search (in one window) is given.
struct CarSearchConfig {
  RobotDef car;
  LotBounds window;
  const MotionValidator* validator = nullptr;
  const FootprintFit* fit = nullptr;  // null: the validator's footprint queries
  const CarAStarDef* def = nullptr;
  const CarTimeCost* cost = nullptr;
  const ReedsSheppSteering* curves = nullptr;
  bool trust_grid = true;  // see TimeAStarSearch.h's TimeSearchConfig
  long max_expansions = 0;
  CarClock::time_point deadline = CarClock::time_point::max();
  const SearchDef* search = nullptr;  // its cancel flag
  const PlanProgress* progress = nullptr;
  long progress_offset = 0;
  long progress_budget = 0;
};

struct CarSearchOutcome {
  enum class Status { kFound, kExhausted, kBudget, kTimeLimit };
  Status status = Status::kExhausted;
  std::vector<PathPiece> pieces;  // found: driven from the start
  long expansions = 0;
  long nodes = 0;
  long analytic_attempts = 0;
  double heuristic_s = 0.0;
  double analytic_s = 0.0;
  double collision_s = 0.0;
};

class CarSearch {
 public:
  CarSearch(const CarSearchConfig& c, const std::vector<Pose2>& sources,
            const std::vector<Pose2>& targets)
      : c_(c), def_(*c.def), validator_(*c.validator), targets_(targets) {
    const double radius = footprintRadius(c.car);
    cell_ = def_.cell_m > 0.0 ? def_.cell_m : 0.125 * radius;
    step_ = def_.step_m > 0.0 ? def_.step_m : 1.5 * cell_;
    speed_ = c.cost->limits().max_speed_mps;
    coarse_ = movesOf(step_);
    const double fine = def_.fine_zone_m < 0.0 ? 2.0 * radius : def_.fine_zone_m;
    cell_keys_ = SearchCells(c.window, {cell_, def_.heading_bins}, fineCells(1), fine, sources);
  }

  CarSearchOutcome run(bool backward);

 private:
  struct Node {
    Pose2 pose;
    double g = 0.0;
    int parent = -1;
    int move = -1;
    bool fine_move = false;
    int direction = 0;  // of the move into the node; 0 at the sources
    double kappa = 0.0;
  };
  struct Cell {
    double g = std::numeric_limits<double>::infinity();
    bool closed = false;
  };
  using Item = std::pair<double, int>;  // f, node; ties by node id (deterministic)

  std::vector<CarMove> movesOf(double step) const;
  CellSize fineCells(int level) const;
  double heuristic(const Pose2& p) const;
  void reset();
  bool expandNext();
  bool tryAnalytic(int id, double h);
  void pushChildren(int id);
  bool edgeValid(const Node& n);
  const std::vector<CarMove>& movesFor(bool fine) const { return fine ? fine_ : coarse_; }

  const CarSearchConfig& c_;
  const CarAStarDef& def_;
  const MotionValidator& validator_;
  std::vector<Pose2> targets_;
  double cell_ = 0.0;
  double step_ = 0.0;
  double speed_ = 0.0;
  SearchCells cell_keys_;
  std::vector<CarMove> coarse_;
  std::vector<CarMove> fine_;
  std::unique_ptr<ObstacleHeuristic> grid_;
  double grid_slack_m_ = 0.0;

  std::vector<Node> nodes_;
  std::unordered_map<std::int64_t, Cell> cells_;
  std::priority_queue<Item, std::vector<Item>, std::greater<>> open_;
  std::vector<PathPiece> analytic_;
  int reached_ = -1;
  CarSearchOutcome out_;
};

std::vector<CarMove> CarSearch::movesOf(double step) const {
  const double kappa_max = c_.car.maxCurvature();
  std::vector<double> radii;
  for (int j = 1; j <= def_.curvature_steps; ++j) {
    radii.push_back(1.0 / (kappa_max * j / def_.curvature_steps));
  }
  std::vector<CarMove> moves;
  for (const MotionPrimitive& p : makePrimitives(step, radii, std::vector<double>{})) {
    const double kappa = p.motion.omega_radps / p.motion.v_mps;
    moves.push_back({p, pieceOf(p, c_.car), kappa, c_.cost->pieceTime(p.length_m, kappa)});
  }
  return moves;
}

CellSize CarSearch::fineCells(int level) const {
  const double scale = std::pow(def_.fine_scale, level);
  return {scale * cell_, static_cast<int>(std::lround(def_.heading_bins / scale))};
}

// Seconds to the nearest target at the speed limit: the larger of the Reeds-Shepp length and the
// grid distance around obstacles (less the grid's own slack); infinite where the grid sees no
// way, unless it is not trusted.
double CarSearch::heuristic(const Pose2& p) const {
  double grid = grid_->distance(p.x, p.y) - grid_slack_m_;
  if (!std::isfinite(grid)) {
    if (c_.trust_grid) return grid;
    grid = 0.0;
  }
  double curve = std::numeric_limits<double>::infinity();
  for (const Pose2& t : targets_) curve = std::min(curve, c_.curves->distance(p, t));
  return std::max(curve, grid) / speed_;
}

void CarSearch::reset() {
  nodes_.clear();
  cells_.clear();
  open_ = {};
  for (const Pose2& p : cell_keys_.sources()) {
    const std::int64_t k = cell_keys_.key(p);
    if (cells_.count(k)) continue;
    const double h = heuristic(p);
    if (!std::isfinite(h)) continue;
    cells_[k].g = 0.0;
    open_.push({c_.def->heuristic_weight * h, static_cast<int>(nodes_.size())});
    nodes_.push_back({p, 0.0, -1, -1, false, 0, 0.0});
  }
}

bool CarSearch::edgeValid(const Node& n) {
  if (n.parent < 0) return true;
  const CarClock::time_point t0 = CarClock::now();
  const bool ok = validator_.isValid(
      geometryOf(nodes_[n.parent].pose, {movesFor(n.fine_move)[n.move].piece}, c_.car));
  out_.collision_s += secondsSince(t0);
  return ok;
}

bool CarSearch::tryAnalytic(int id, double h) {
  const long n = out_.expansions;
  if (!(h < def_.analytic_near_s) && def_.analytic_interval > 1 &&
      n % def_.analytic_interval != 1) {
    return false;
  }
  const CarClock::time_point t0 = CarClock::now();
  const Pose2 from = nodes_[id].pose;
  for (const Pose2& t : targets_) {
    ++out_.analytic_attempts;
    std::vector<PathPiece> curve = c_.curves->pieces(from, t);
    if (validator_.isValid(geometryOf(from, curve, c_.car))) {
      analytic_ = std::move(curve);
      reached_ = id;
      break;
    }
  }
  out_.analytic_s += secondsSince(t0);
  return reached_ >= 0;
}

void CarSearch::pushChildren(int id) {
  const Node n = nodes_[id];
  const bool fine = cell_keys_.inFineZone(n.pose);
  const std::vector<CarMove>& moves = movesFor(fine);
  for (int m = 0; m < static_cast<int>(moves.size()); ++m) {
    const CarMove& move = moves[m];
    const Pose2 next = applyPrimitive(n.pose, move.primitive);
    if (!c_.window.contains(next.x, next.y)) continue;
    const std::int64_t k = cell_keys_.key(next);
    auto it = cells_.find(k);
    if (it != cells_.end() && it->second.closed) continue;
    // The sources are where the search starts: no junction there.
    const double junction =
        n.direction == 0 ? 0.0
                         : c_.cost->junctionTime(n.direction, n.kappa, move.primitive.direction,
                                                 move.kappa, 0.5 * move.primitive.length_m);
    const double g = n.g + move.time_s + junction;
    if (it != cells_.end() && it->second.g <= g) continue;
    const double h = heuristic(next);
    if (!std::isfinite(h)) continue;
    cells_[k].g = g;
    open_.push({g + c_.def->heuristic_weight * h, static_cast<int>(nodes_.size())});
    nodes_.push_back({next, g, id, m, fine, move.primitive.direction, move.kappa});
  }
}

bool CarSearch::expandNext() {
  while (!open_.empty()) {
    const auto [f, id] = open_.top();
    open_.pop();
    const Node& n = nodes_[id];
    Cell& cell = cells_[cell_keys_.key(n.pose)];
    if (cell.closed || n.g > cell.g) continue;
    if (!edgeValid(n)) {
      cell.g = std::numeric_limits<double>::infinity();  // others may reach the cell after all
      continue;
    }
    cell.closed = true;
    ++out_.expansions;
    if (c_.progress && *c_.progress) {
      (*c_.progress)(c_.progress_offset + out_.expansions, c_.progress_budget);
    }
    if (tryAnalytic(id, (f - nodes_[id].g) / c_.def->heuristic_weight)) return false;
    pushChildren(id);
    return true;
  }
  return false;
}

CarSearchOutcome CarSearch::run(bool backward) {
  const CarClock::time_point t0 = CarClock::now();
  const double longer = std::max(cell_keys_.width_m(), cell_keys_.height_m());
  const double grid_cell =
      std::max(def_.heuristic_cell_m > 0.0 ? def_.heuristic_cell_m : 2.0 * cell_,
               longer / def_.max_heuristic_cells_per_side);
  grid_ = c_.fit ? std::make_unique<ObstacleHeuristic>(
                       [&](double x, double y) { return c_.fit->fitsSomeHeading(x, y); }, c_.window,
                       grid_cell, targets_.front())
                 : std::make_unique<ObstacleHeuristic>(validator_, c_.window, grid_cell,
                                                       targets_.front());
  grid_slack_m_ = std::sqrt(2.0) * grid_cell;
  out_.heuristic_s = secondsSince(t0);
  // Coarse, then finer near the sources twice.
  for (int attempt = 0; attempt < 3 && reached_ < 0; ++attempt) {
    if (attempt >= 1) {
      if (cell_keys_.fineZone_m() <= 0.0) break;
      cell_keys_.enableFineZone();
      cell_keys_.setFine(fineCells(attempt));
      fine_ = movesOf(std::pow(def_.fine_scale, attempt) * step_);
    }
    reset();
    while (expandNext()) {
      if (out_.expansions >= c_.max_expansions) {
        out_.status = CarSearchOutcome::Status::kBudget;
        out_.nodes += static_cast<long>(nodes_.size());
        return std::move(out_);
      }
      if (CarClock::now() > c_.deadline || c_.search->cancelled()) {
        out_.status = CarSearchOutcome::Status::kTimeLimit;
        out_.nodes += static_cast<long>(nodes_.size());
        return std::move(out_);
      }
    }
    out_.nodes += static_cast<long>(nodes_.size());
  }
  if (reached_ < 0) {
    out_.status = CarSearchOutcome::Status::kExhausted;
    return std::move(out_);
  }
  std::vector<int> chain;
  for (int i = reached_; nodes_[i].parent >= 0; i = nodes_[i].parent) chain.push_back(i);
  std::reverse(chain.begin(), chain.end());
  std::vector<PathPiece> pieces;
  for (int i : chain) pieces.push_back(movesFor(nodes_[i].fine_move)[nodes_[i].move].piece);
  pieces.insert(pieces.end(), analytic_.begin(), analytic_.end());
  if (backward) {
    // Driven the other way round: the pieces in reverse order, each with its wheels reversed.
    std::reverse(pieces.begin(), pieces.end());
    for (PathPiece& p : pieces) p.direction = {-p.direction.left_radps, -p.direction.right_radps};
  }
  for (const PathPiece& p : pieces) appendPiece(out_.pieces, p);
  out_.status = CarSearchOutcome::Status::kFound;
  return std::move(out_);
}

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
  CarSearchConfig config;
  config.car = car_;
  config.validator = &validator_;
  config.fit = fit.get();
  config.def = &search_;
  config.cost = &cost;
  config.curves = &curves;
  config.max_expansions = def_.max_iterations;
  if (def_.max_time_s > 0.0) {
    config.deadline = t_begin + std::chrono::duration_cast<CarClock::duration>(
                                    std::chrono::duration<double>(def_.max_time_s));
  }
  config.search = &def_;
  config.progress = &progress;
  config.progress_budget = def_.max_iterations;
  const bool backward = search_.from_goal;
  const std::vector<Pose2> sources = backward ? roots : std::vector<Pose2>{start};
  const std::vector<Pose2> targets = backward ? std::vector<Pose2>{start} : roots;
  double margin = firstMargin(search_.window, start, goal.pose);
  PlanStats& st = result.stats;
  CarSearchOutcome out;
  while (true) {
    config.window = searchWindow(lot_, start, goal.pose, margin);
    config.progress_offset = st.iterations;
    config.max_expansions = def_.max_iterations - st.iterations;
    out = CarSearch(config, sources, targets).run(backward);
    st.iterations += static_cast<int>(out.expansions);
    st.tree_size += static_cast<int>(out.nodes);
    st.goal_attempts += static_cast<int>(out.analytic_attempts);
    st.times.heuristic_s += out.heuristic_s;
    st.times.goal_check_s += out.analytic_s;
    st.times.collision_s += out.collision_s;
    if (out.status != CarSearchOutcome::Status::kExhausted) break;
    if (coversLot(config.window, lot_)) {
      if (!config.trust_grid) break;
      config.trust_grid = false;  // a passage may have hidden from the grid: look there too
      continue;
    }
    margin *= 2.0;  // hemmed in by the window: look wider
  }
  st.goal_tree_size = static_cast<int>(roots.size());
  if (out.status != CarSearchOutcome::Status::kFound) {
    if (def_.cancelled()) {
      return finish(PlanStatus::kCancelled,
                    "cancelled before a collision-free trajectory to the goal was found");
    }
    if (out.status == CarSearchOutcome::Status::kTimeLimit) {
      return finish(PlanStatus::kTimeLimit, "no collision-free trajectory to the goal within " +
                                                std::to_string(def_.max_time_s) + " s");
    }
    return finish(PlanStatus::kIterationLimit,
                  out.status == CarSearchOutcome::Status::kExhausted
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
