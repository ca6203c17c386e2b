#include "parksim/planner/HybridAStar.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <queue>
#include <unordered_map>

#include "parksim/core/Error.h"
#include "parksim/core/Geometry.h"
#include "parksim/planner/MotionPrimitives.h"
#include "parksim/planner/ObstacleHeuristic.h"
#include "parksim/planner/PathCost.h"

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
                         const PlannerDef& def, const HybridAStarDef& hybrid)
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

PlanResult HybridAStar::solve(const Pose2& start, const GoalRegion& goal,
                              const PlanProgress& progress) const {
  const Clock::time_point t_begin = Clock::now();
  const long queries_before = validator_.queries();
  PlanResult result;
  PlanStats& st = result.stats;
  auto finish = [&](PlanStatus status, std::string message) {
    result.status = status;
    result.message = std::move(message);
    st.collision_queries = validator_.queries() - queries_before;
    st.times.total_s = seconds(t_begin);
    return std::move(result);
  };
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

  // The search grows from `sources` and its analytic expansions aim at `targets`.
  const bool backward = hybrid_.from_goal;
  const std::vector<Pose2> sources = backward ? roots : std::vector<Pose2>{start};
  const std::vector<Pose2> targets = backward ? std::vector<Pose2>{start} : roots;

  const double width = lot_.x_max_m - lot_.x_min_m;
  const double height = lot_.y_max_m - lot_.y_min_m;
  double cell = hybrid_.cell_m > 0.0 ? hybrid_.cell_m : 0.25 * footprintRadius(robot_);
  if (hybrid_.cell_m <= 0.0) cell = std::max(cell, std::max(width, height) / kMaxCellsPerSide);
  const double step = hybrid_.step_m > 0.0 ? hybrid_.step_m : 1.5 * cell;
  std::vector<double> radii{reeds_shepp_.def().turning_radius_m};
  if (hybrid_.tight_turning_radius_m > 0.0) radii.push_back(hybrid_.tight_turning_radius_m);
  const std::vector<MotionPrimitive> coarse =
      makePrimitives(step, radii, hybrid_.turn_in_place_rad);
  const std::vector<MotionPrimitive> fine =
      makePrimitives(hybrid_.fine_step_m, radii, hybrid_.fine_turn_in_place_rad);
  const double fine_zone =
      hybrid_.fine_zone_m < 0.0 ? 2.0 * footprintRadius(robot_) : hybrid_.fine_zone_m;
  bool fine_on = false;  // the first attempt is coarse everywhere
  auto inFineZone = [&](const Pose2& p) {
    if (!fine_on) return false;
    for (const Pose2& q : sources) {
      if (positionDistance(p, q) < fine_zone) return true;
    }
    return false;
  };
  const double turn_cost_per_rad = footprintRadius(robot_);

  std::unique_ptr<ObstacleHeuristic> grid;
  {
    const Clock::time_point t0 = Clock::now();
    grid = std::make_unique<ObstacleHeuristic>(validator_, lot_, cell, targets.front());
    st.times.heuristic_s = seconds(t0);
  }
  const double cell_diag = std::sqrt(2.0) * cell;
  auto heuristic = [&](const Pose2& p) {
    double rs = std::numeric_limits<double>::infinity();
    for (const Pose2& r : targets) rs = std::min(rs, reeds_shepp_.distance(p, r));
    return std::max(rs, grid->distance(p.x, p.y) - cell_diag);
  };

  // Coarse and fine cells are numbered apart: the fine ones after every coarse one.
  auto cellKey = [&](const Pose2& p, double c, int nh, std::int64_t offset) {
    const auto nx = static_cast<std::int64_t>(std::ceil(width / c)) + 1;
    const auto ny = static_cast<std::int64_t>(std::ceil(height / c)) + 1;
    const auto i = static_cast<std::int64_t>(std::floor((p.x - lot_.x_min_m) / c));
    const auto j = static_cast<std::int64_t>(std::floor((p.y - lot_.y_min_m) / c));
    const double turns = wrapAngle(p.theta) / (2.0 * kPi) + 0.5;  // [0, 1]
    const auto k = static_cast<std::int64_t>(std::floor(turns * nh + 0.5)) % nh;
    return offset + (k * ny + j) * nx + i;
  };
  const std::int64_t coarse_cells = (static_cast<std::int64_t>(std::ceil(width / cell)) + 1) *
                                    (static_cast<std::int64_t>(std::ceil(height / cell)) + 1) *
                                    hybrid_.heading_bins;
  auto key = [&](const Pose2& p) {
    return inFineZone(p) ? cellKey(p, hybrid_.fine_cell_m, hybrid_.fine_heading_bins, coarse_cells)
                         : cellKey(p, cell, hybrid_.heading_bins, 0);
  };

  std::vector<Node> nodes;
  std::unordered_map<std::int64_t, int> best;  // cell -> node with the lowest g so far
  std::unordered_map<std::int64_t, char> closed;
  using Item = std::pair<double, int>;  // f, node; ties broken by node id (deterministic)
  std::priority_queue<Item, std::vector<Item>, std::greater<>> open;
  std::vector<PathPiece> expansion;  // the analytic curve that reached the goal
  int reached_from = -1;
  bool timed_out = false;
  int expansions = 0;
  // Coarse first; if that runs out of cells to expand (the sources are hemmed in), once more
  // with the fine zone, on what is left of the budget.
  for (int attempt = 0; attempt < 2 && reached_from < 0 && !timed_out; ++attempt) {
    if (attempt == 1) {
      if (!open.empty() || fine_zone <= 0.0) break;
      fine_on = true;
      nodes.clear();
      best.clear();
      closed.clear();
    }
    for (const Pose2& p : sources) {
      if (best.count(key(p))) continue;
      best[key(p)] = static_cast<int>(nodes.size());
      open.push({hybrid_.heuristic_weight * heuristic(p), static_cast<int>(nodes.size())});
      nodes.push_back({p, 0.0, -1, -1, 0, false});
    }

    while (!open.empty() && expansions < def_.max_iterations) {
      if (def_.max_time_s > 0.0 && seconds(t_begin) > def_.max_time_s) {
        timed_out = true;
        break;
      }
      const auto [f, id] = open.top();
      open.pop();
      const std::int64_t k = key(nodes[id].pose);
      if (closed.count(k) || best[k] != id) continue;
      closed[k] = 1;
      ++expansions;
      if (progress) progress(expansions, def_.max_iterations);
      const Node n = nodes[id];
      const double h = (f - n.g) / hybrid_.heuristic_weight;

      if (h < hybrid_.analytic_near_steps * step || expansions % hybrid_.analytic_interval == 1 ||
          hybrid_.analytic_interval == 1) {
        const Clock::time_point t0 = Clock::now();
        for (const Pose2& r : targets) {
          ++st.goal_attempts;
          std::vector<PathPiece> curve = reeds_shepp_.pieces(n.pose, r);
          if (validator_.isValid(geometryOf(n.pose, curve, robot_))) {
            expansion = std::move(curve);
            reached_from = id;
            break;
          }
        }
        st.times.goal_check_s += seconds(t0);
        if (reached_from >= 0) break;
      }

      const bool in_fine = inFineZone(n.pose);
      const std::vector<MotionPrimitive>& primitives = in_fine ? fine : coarse;
      for (int m = 0; m < static_cast<int>(primitives.size()); ++m) {
        const MotionPrimitive& prim = primitives[m];
        Pose2 next;
        {
          const Clock::time_point t0 = Clock::now();
          next = applyPrimitive(n.pose, prim);
          st.times.steering_s += seconds(t0);
        }
        if (!lot_.contains(next.x, next.y)) continue;
        const std::int64_t nk = key(next);
        if (closed.count(nk)) continue;
        // Searching backwards, a move forward here is driven in reverse.
        const bool driven_reverse = backward ? prim.direction > 0 : prim.direction < 0;
        double g = n.g + prim.length_m * (driven_reverse ? 1.0 + def_.reverse_penalty : 1.0) +
                   (prim.direction == 0 ? turn_cost_per_rad * prim.turn_rad : 0.0);
        const bool cusp =
            prim.direction != 0 && n.last_direction != 0 && prim.direction != n.last_direction;
        if (cusp) g += def_.cusp_penalty_m;
        const auto it = best.find(nk);
        if (it != best.end() && nodes[it->second].g <= g) continue;
        {
          const Clock::time_point t0 = Clock::now();
          const bool ok = validator_.isValid(geometryOf(n.pose, {pieceOf(prim, robot_)}, robot_));
          st.times.collision_s += seconds(t0);
          if (!ok) continue;
        }
        const int child = static_cast<int>(nodes.size());
        nodes.push_back(
            {next, g, id, m, prim.direction != 0 ? prim.direction : n.last_direction, in_fine});
        best[nk] = child;
        open.push({g + hybrid_.heuristic_weight * heuristic(next), child});
      }
    }
  }
  st.iterations = expansions;
  st.tree_size = static_cast<int>(nodes.size());
  st.goal_tree_size = static_cast<int>(roots.size());

  if (reached_from < 0) {
    if (timed_out) {
      return finish(PlanStatus::kTimeLimit, "no collision-free trajectory to the goal within " +
                                                std::to_string(def_.max_time_s) + " s");
    }
    return finish(PlanStatus::kIterationLimit,
                  open.empty() ? "no collision-free trajectory to the goal: every reachable cell "
                                 "was expanded"
                               : "no collision-free trajectory to the goal within " +
                                     std::to_string(def_.max_iterations) + " expansions");
  }
  std::vector<int> chain;
  for (int i = reached_from; nodes[i].parent >= 0; i = nodes[i].parent) chain.push_back(i);
  std::reverse(chain.begin(), chain.end());
  std::vector<PathPiece> pieces;
  for (int i : chain) {
    const Node& c = nodes[i];
    pieces.push_back(pieceOf((c.fine_move ? fine : coarse)[c.primitive], robot_));
  }
  pieces.insert(pieces.end(), expansion.begin(), expansion.end());
  if (backward) {
    // Driven the other way round: the pieces in reverse order, each with its wheels reversed.
    std::reverse(pieces.begin(), pieces.end());
    for (PathPiece& p : pieces) p.direction = {-p.direction.left_radps, -p.direction.right_radps};
  }
  std::vector<PathPiece> merged;
  for (const PathPiece& p : pieces) appendPiece(merged, p);
  pieces = std::move(merged);
  const TimingLimits limits{robot_.max_wheel_speed_radps, robot_.max_wheel_accel_radps2, 0.1};
  Trajectory traj = timePieces(start, pieces, robot_, limits);
  if (!validator_.isValid(traj)) {
    return finish(PlanStatus::kIterationLimit,
                  "the joined plan failed its whole-path check (rounding); no plan");
  }
  const CostWeights w{def_.reverse_penalty, def_.cusp_penalty_m};
  result.cost = trajectoryCost(traj, robot_, w);
  result.trajectory = std::move(traj);
  result.waypoints = {start, nodes[reached_from].pose, result.trajectory.points.back().pose};
  st.first_solution_s = seconds(t_begin);
  st.first_solution_iteration = expansions;
  result.cost_history.push_back({st.first_solution_s, expansions, result.cost});
  return finish(PlanStatus::kSolved, "solved");
}

}  // namespace parksim
