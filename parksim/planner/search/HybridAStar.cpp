#include "parksim/planner/search/HybridAStar.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <queue>
#include <unordered_map>

#include "parksim/core/io/Error.h"
#include "parksim/core/model/Geometry.h"
#include "parksim/planner/motion/MotionPrimitives.h"
#include "parksim/planner/motion/PathCost.h"
#include "parksim/planner/search/ObstacleHeuristic.h"
#include "parksim/planner/search/SearchCells.h"

namespace parksim {

namespace {

using Clock = std::chrono::steady_clock;

// Lots wider than this many default cells get larger cells, bounding the grids' size.
constexpr double kMaxCellsPerSide = 250.0;

double seconds(Clock::time_point since) {
  return std::chrono::duration<double>(Clock::now() - since).count();
}

struct Node {
  Pose2 pose;
  double g = 0.0;
  int parent = -1;
  int primitive = -1;  // the move from the parent
  int last_direction = 0;
  bool fine_move = false;  // the move is one of the fine zone's primitives
};

}  // namespace

HybridAStar::HybridAStar(const RobotDef& robot, const LotBounds& lot,
                         const ReedsSheppSteering& reeds_shepp, const MotionValidator& validator,
                         const SearchDef& def, const HybridAStarDef& hybrid)
    : robot_(robot),
      lot_(lot),
      reeds_shepp_(reeds_shepp),
      validator_(validator),
      def_(def),
      hybrid_(hybrid) {
  if (def.max_iterations < 0) throw Error("planner: max_iterations must be >= 0");
  if (!(def.max_time_s >= 0.0)) throw Error("planner: max_time_s must be >= 0");
  if (!(def.reverse_penalty >= 0.0) || !(def.cusp_penalty_m >= 0.0)) {
    throw Error("planner: reverse_penalty and cusp_penalty_m must be >= 0");
  }
  if (!(hybrid.cell_m >= 0.0) || !(hybrid.step_m >= 0.0) || hybrid.heading_bins < 4 ||
      !(hybrid.turn_in_place_rad >= 0.0) || !(hybrid.fine_cell_m > 0.0) ||
      hybrid.fine_heading_bins < 4 || !(hybrid.fine_step_m > 0.0) ||
      !(hybrid.fine_turn_in_place_rad >= 0.0) || hybrid.analytic_interval < 1 ||
      !(hybrid.heuristic_weight >= 1.0)) {
    throw Error(
        "hybrid A*: cell and step must be >= 0, heading_bins >= 4, analytic_interval >= 1, "
        "heuristic_weight >= 1");
  }
}

namespace {

// One call of HybridAStar::solve: the grids, the nodes and the result being built.
class Search {
 public:
  Search(const RobotDef& robot, const LotBounds& lot, const ReedsSheppSteering& reeds_shepp,
         const MotionValidator& validator, const SearchDef& def, const HybridAStarDef& hybrid,
         const PlanProgress& progress)
      : robot_(robot),
        lot_(lot),
        reeds_shepp_(reeds_shepp),
        validator_(validator),
        def_(def),
        hybrid_(hybrid),
        progress_(progress),
        t_begin_(Clock::now()),
        queries_before_(validator.queries()) {}

  PlanResult run(const Pose2& start, const GoalRegion& goal);

 private:
  using Item = std::pair<double, int>;  // f, node; ties broken by node id (deterministic)

  PlanResult finish(PlanStatus status, std::string message);
  void prepare(const std::vector<Pose2>& sources, const std::vector<Pose2>& targets);
  double heuristic(const Pose2& p) const;
  void search();
  bool tryAnalytic(int id, double h);
  void expand(int id);
  PlanResult result(const Pose2& start);

  const RobotDef& robot_;
  const LotBounds& lot_;
  const ReedsSheppSteering& reeds_shepp_;
  const MotionValidator& validator_;
  const SearchDef& def_;
  const HybridAStarDef& hybrid_;
  const PlanProgress& progress_;
  const Clock::time_point t_begin_;
  const long queries_before_;
  PlanResult result_;

  // The search grows from `cell_keys_.sources()` and its analytic expansions aim at `targets_`.
  bool backward_ = true;
  std::vector<Pose2> targets_;
  SearchCells cell_keys_;  // the first attempt is coarse everywhere
  double cell_ = 0.0;
  double step_ = 0.0;
  double turn_cost_per_rad_ = 0.0;
  std::vector<MotionPrimitive> coarse_;
  std::vector<MotionPrimitive> fine_;
  std::unique_ptr<ObstacleHeuristic> grid_;

  std::vector<Node> nodes_;
  std::unordered_map<std::int64_t, int> best_;  // cell -> node with the lowest g so far
  std::unordered_map<std::int64_t, char> closed_;
  std::priority_queue<Item, std::vector<Item>, std::greater<>> open_;
  std::vector<PathPiece> expansion_;  // the analytic curve that reached the goal
  int reached_from_ = -1;
  bool timed_out_ = false;
  int expansions_ = 0;
};

PlanResult Search::finish(PlanStatus status, std::string message) {
  result_.status = status;
  result_.message = std::move(message);
  result_.stats.collision_queries = validator_.queries() - queries_before_;
  result_.stats.times.total_s = seconds(t_begin_);
  return std::move(result_);
}

// Cells, moves and the obstacle heuristic's grid for this lot.
void Search::prepare(const std::vector<Pose2>& sources, const std::vector<Pose2>& targets) {
  targets_ = targets;
  const double width = lot_.x_max_m - lot_.x_min_m;
  const double height = lot_.y_max_m - lot_.y_min_m;
  cell_ = hybrid_.cell_m > 0.0 ? hybrid_.cell_m : 0.25 * footprintRadius(robot_);
  if (hybrid_.cell_m <= 0.0) cell_ = std::max(cell_, std::max(width, height) / kMaxCellsPerSide);
  step_ = hybrid_.step_m > 0.0 ? hybrid_.step_m : 1.5 * cell_;
  std::vector<double> radii{reeds_shepp_.def().turning_radius_m};
  if (hybrid_.tight_turning_radius_m > 0.0) radii.push_back(hybrid_.tight_turning_radius_m);
  coarse_ = makePrimitives(step_, radii, hybrid_.turn_in_place_rad);
  fine_ = makePrimitives(hybrid_.fine_step_m, radii, hybrid_.fine_turn_in_place_rad);
  cell_keys_ = SearchCells(
      lot_, {cell_, hybrid_.heading_bins}, {hybrid_.fine_cell_m, hybrid_.fine_heading_bins},
      hybrid_.fine_zone_m < 0.0 ? 2.0 * footprintRadius(robot_) : hybrid_.fine_zone_m, sources);
  turn_cost_per_rad_ = footprintRadius(robot_);
  const Clock::time_point t0 = Clock::now();
  grid_ = std::make_unique<ObstacleHeuristic>(validator_, lot_, cell_, targets_.front());
  result_.stats.times.heuristic_s = seconds(t0);
}

double Search::heuristic(const Pose2& p) const {
  double rs = std::numeric_limits<double>::infinity();
  for (const Pose2& r : targets_) rs = std::min(rs, reeds_shepp_.distance(p, r));
  return std::max(rs, grid_->distance(p.x, p.y) - std::sqrt(2.0) * cell_);
}

// The analytic expansion from node `id`, when it is due: the Reeds-Shepp curve to a target.
bool Search::tryAnalytic(int id, double h) {
  if (!(h < hybrid_.analytic_near_steps * step_ || expansions_ % hybrid_.analytic_interval == 1 ||
        hybrid_.analytic_interval == 1)) {
    return false;
  }
  const Clock::time_point t0 = Clock::now();
  for (const Pose2& r : targets_) {
    ++result_.stats.goal_attempts;
    std::vector<PathPiece> curve = reeds_shepp_.pieces(nodes_[id].pose, r);
    if (validator_.isValid(geometryOf(nodes_[id].pose, curve, robot_))) {
      expansion_ = std::move(curve);
      reached_from_ = id;
      break;
    }
  }
  result_.stats.times.goal_check_s += seconds(t0);
  return reached_from_ >= 0;
}

// Every move from node `id` into a cell not closed and not reached more cheaply, validated.
void Search::expand(int id) {
  PhaseTimes& times = result_.stats.times;
  const Node n = nodes_[id];
  const bool in_fine = cell_keys_.inFineZone(n.pose);
  const std::vector<MotionPrimitive>& primitives = in_fine ? fine_ : coarse_;
  for (int m = 0; m < static_cast<int>(primitives.size()); ++m) {
    const MotionPrimitive& prim = primitives[m];
    Pose2 next;
    {
      const Clock::time_point t0 = Clock::now();
      next = applyPrimitive(n.pose, prim);
      times.steering_s += seconds(t0);
    }
    if (!lot_.contains(next.x, next.y)) continue;
    const std::int64_t nk = cell_keys_.key(next);
    if (closed_.count(nk)) continue;
    // Searching backwards, a move forward here is driven in reverse.
    const bool driven_reverse = backward_ ? prim.direction > 0 : prim.direction < 0;
    double g = n.g + prim.length_m * (driven_reverse ? 1.0 + def_.reverse_penalty : 1.0) +
               (prim.direction == 0 ? turn_cost_per_rad_ * prim.turn_rad : 0.0);
    const bool cusp =
        prim.direction != 0 && n.last_direction != 0 && prim.direction != n.last_direction;
    if (cusp) g += def_.cusp_penalty_m;
    const auto it = best_.find(nk);
    if (it != best_.end() && nodes_[it->second].g <= g) continue;
    {
      const Clock::time_point t0 = Clock::now();
      const bool ok = validator_.isValid(geometryOf(n.pose, {pieceOf(prim, robot_)}, robot_));
      times.collision_s += seconds(t0);
      if (!ok) continue;
    }
    const int child = static_cast<int>(nodes_.size());
    nodes_.push_back(
        {next, g, id, m, prim.direction != 0 ? prim.direction : n.last_direction, in_fine});
    best_[nk] = child;
    open_.push({g + hybrid_.heuristic_weight * heuristic(next), child});
  }
}

// Coarse first; if that runs out of cells to expand (the sources are hemmed in), once more
// with the fine zone, on what is left of the budget.
void Search::search() {
  for (int attempt = 0; attempt < 2 && reached_from_ < 0 && !timed_out_; ++attempt) {
    if (attempt == 1) {
      if (!open_.empty() || cell_keys_.fineZone_m() <= 0.0) break;
      cell_keys_.enableFineZone();
      nodes_.clear();
      best_.clear();
      closed_.clear();
    }
    for (const Pose2& p : cell_keys_.sources()) {
      if (best_.count(cell_keys_.key(p))) continue;
      best_[cell_keys_.key(p)] = static_cast<int>(nodes_.size());
      open_.push({hybrid_.heuristic_weight * heuristic(p), static_cast<int>(nodes_.size())});
      nodes_.push_back({p, 0.0, -1, -1, 0, false});
    }
    while (!open_.empty() && expansions_ < def_.max_iterations) {
      if ((def_.max_time_s > 0.0 && seconds(t_begin_) > def_.max_time_s) || def_.cancelled()) {
        timed_out_ = true;
        break;
      }
      const auto [f, id] = open_.top();
      open_.pop();
      const std::int64_t k = cell_keys_.key(nodes_[id].pose);
      if (closed_.count(k) || best_[k] != id) continue;
      closed_[k] = 1;
      ++expansions_;
      if (progress_) progress_(expansions_, def_.max_iterations);
      if (tryAnalytic(id, (f - nodes_[id].g) / hybrid_.heuristic_weight)) break;
      expand(id);
    }
  }
}

// The plan from the start: the moves to the node the analytic curve left from and the curve,
// driven the other way round when searching backwards, timed at the wheel limits.
PlanResult Search::result(const Pose2& start) {
  std::vector<int> chain;
  for (int i = reached_from_; nodes_[i].parent >= 0; i = nodes_[i].parent) chain.push_back(i);
  std::reverse(chain.begin(), chain.end());
  std::vector<PathPiece> pieces;
  for (int i : chain) {
    const Node& c = nodes_[i];
    pieces.push_back(pieceOf((c.fine_move ? fine_ : coarse_)[c.primitive], robot_));
  }
  pieces.insert(pieces.end(), expansion_.begin(), expansion_.end());
  if (backward_) {
    std::reverse(pieces.begin(), pieces.end());
    for (PathPiece& p : pieces) p.direction = {-p.direction.left_radps, -p.direction.right_radps};
  }
  std::vector<PathPiece> merged;
  for (const PathPiece& p : pieces) appendPiece(merged, p);
  const TimingLimits limits{robot_.max_wheel_speed_radps, robot_.max_wheel_accel_radps2, 0.1};
  Trajectory traj = timePieces(start, merged, robot_, limits);
  if (!validator_.isValid(traj)) {
    return finish(PlanStatus::kIterationLimit,
                  "the joined plan failed its whole-path check (rounding); no plan");
  }
  const CostWeights w{def_.reverse_penalty, def_.cusp_penalty_m};
  result_.cost = trajectoryCost(traj, robot_, w);
  result_.trajectory = std::move(traj);
  result_.waypoints = {start, nodes_[reached_from_].pose, result_.trajectory.points.back().pose};
  result_.stats.first_solution_s = seconds(t_begin_);
  result_.stats.first_solution_iteration = expansions_;
  result_.cost_history.push_back({result_.stats.first_solution_s, expansions_, result_.cost});
  return finish(PlanStatus::kSolved, "solved");
}

PlanResult Search::run(const Pose2& start, const GoalRegion& goal) {
  if (!validator_.isValid(start)) {
    return finish(PlanStatus::kInvalidStart, validator_.insideLot(start)
                                                 ? "start pose collides"
                                                 : "start pose lies within half the motion-check "
                                                   "resolution of the lot edge");
  }
  std::vector<Pose2> roots;
  for (const Pose2& g : {goal.pose, Pose2{goal.pose.x, goal.pose.y, goal.pose.theta + kPi}}) {
    if (roots.size() == 1 && !goal.either_heading) break;
    if (validator_.isValid(g)) roots.push_back(g);
    if (!goal.either_heading) break;
  }
  if (roots.empty()) {
    return finish(PlanStatus::kInvalidGoal, validator_.insideLot(goal.pose)
                                                ? "goal pose collides"
                                                : "goal pose lies within half the motion-check "
                                                  "resolution of the lot edge");
  }
  backward_ = hybrid_.from_goal;
  prepare(backward_ ? roots : std::vector<Pose2>{start},
          backward_ ? std::vector<Pose2>{start} : roots);
  search();
  PlanStats& st = result_.stats;
  st.iterations = expansions_;
  st.tree_size = static_cast<int>(nodes_.size());
  st.goal_tree_size = static_cast<int>(roots.size());
  if (reached_from_ < 0) {
    if (def_.cancelled()) {
      return finish(PlanStatus::kCancelled,
                    "cancelled before a collision-free trajectory to "
                    "the goal was found");
    }
    if (timed_out_) {
      return finish(PlanStatus::kTimeLimit, "no collision-free trajectory to the goal within " +
                                                std::to_string(def_.max_time_s) + " s");
    }
    return finish(PlanStatus::kIterationLimit,
                  open_.empty() ? "no collision-free trajectory to the goal: every reachable "
                                  "cell was expanded"
                                : "no collision-free trajectory to the goal within " +
                                      std::to_string(def_.max_iterations) + " expansions");
  }
  return result(start);
}

}  // namespace

PlanResult HybridAStar::solve(const Pose2& start, const GoalRegion& goal,
                              const PlanProgress& progress) const {
  return Search(robot_, lot_, reeds_shepp_, validator_, def_, hybrid_, progress).run(start, goal);
}

}  // namespace parksim
