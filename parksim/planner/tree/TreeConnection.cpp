#include "parksim/planner/tree/TreeSearch.h"

#include <algorithm>
#include <cmath>

#include "parksim/core/model/Geometry.h"
#include "parksim/planner/tree/ShortcutSmoother.h"

namespace parksim::detail {

// After start-tree node s was added: try to reach the goal side from it.
void TreeSearch::connectToGoal(int s) {
  if (optimize_) {
    tryGoalLeaves(s);
    return;
  }
  PlanStats& st = result_.stats;
  int g;
  {
    PhaseTimer timer(st.times.nearest_s);
    g = goal_tree_.nearest(start_tree_[s].pose);
  }
  const Node& from = start_tree_[s];
  const Node& to = goal_tree_[g];
  if (def_.variant == TreeVariant::kRrt &&
      goal_tree_.distance(from.pose, to.pose) > def_.connect_radius_m) {
    return;
  }
  PhaseTimer timer(bidirectional_ ? st.times.connection_s : st.times.goal_check_s);
  ++(bidirectional_ ? st.connection_attempts : st.goal_attempts);
  SteerResult bridge = steering_.steer(from.pose, from.arrival, to.pose,
                                       to.parent < 0 ? SteerMode::kToGoal : SteerMode::kExact);
  if (!bridge.reached) return;
  std::vector<PathSegment> plan = startPath(s);
  plan.push_back({std::move(bridge.trajectory), from.arrival == WheelSpeeds{}});
  appendGoalPath(g, plan);
  acceptSolution(std::move(plan));
}

// After goal-tree node g was added: try to reach it from the nearest start-tree node.
void TreeSearch::connectFromStart(int g) {
  PlanStats& st = result_.stats;
  int s;
  {
    PhaseTimer timer(st.times.nearest_s);
    s = start_tree_.nearest(goal_tree_[g].pose);
  }
  PhaseTimer timer(st.times.connection_s);
  ++st.connection_attempts;
  const Node& from = start_tree_[s];
  SteerResult bridge =
      steering_.steer(from.pose, from.arrival, goal_tree_[g].pose, SteerMode::kExact);
  if (!bridge.reached) return;
  std::vector<PathSegment> plan = startPath(s);
  plan.push_back({std::move(bridge.trajectory), from.arrival == WheelSpeeds{}});
  appendGoalPath(g, plan);
  acceptSolution(std::move(plan));
}

// RRT*: to-goal trajectories from rest node s to the goal roots, kept as goal leaves when they
// could beat the best solution.
void TreeSearch::tryGoalLeaves(int s) {
  PlanStats& st = result_.stats;
  std::vector<int> roots = roots_;
  const Pose2 x = start_tree_[s].pose;
  std::sort(roots.begin(), roots.end(), [&](int a, int b) {
    return goal_tree_.distance(x, goal_tree_[a].pose) < goal_tree_.distance(x, goal_tree_[b].pose);
  });
  for (int r : roots) {
    const Node& from = start_tree_[s];
    const Pose2& target = goal_tree_[r].pose;
    if (best_leaf_ >= 0 && from.cost + positionDistance(x, target) >= best_cost_ - kCostEpsilonM) {
      continue;
    }
    PhaseTimer timer(st.times.goal_check_s);
    ++st.goal_attempts;
    SteerResult edge = steering_.steer(x, {}, target, SteerMode::kToGoal);
    if (!edge.reached) continue;
    Node leaf = childOf(s, std::move(edge), true);
    if (best_leaf_ >= 0 && leaf.cost >= best_cost_ - kCostEpsilonM) continue;
    if (!validator_.isValid(leaf.edge.trajectory)) continue;
    leaf.goal_leaf = true;
    leaf.arrival = {};
    best_cost_ = leaf.cost;
    best_leaf_ = start_tree_.add(std::move(leaf), false);
    if (!solved_) {
      solved_ = true;
      result_.stats.first_solution_s = elapsed();
      result_.stats.first_solution_iteration = iteration_;
    }
    recordCost(best_cost_);
  }
}

std::vector<PathSegment> TreeSearch::startPath(int id) const {
  std::vector<PathSegment> plan;
  for (int n = id; start_tree_[n].parent >= 0; n = start_tree_[n].parent) {
    plan.push_back(start_tree_[n].edge);
  }
  std::reverse(plan.begin(), plan.end());
  return plan;
}

void TreeSearch::appendGoalPath(int g, std::vector<PathSegment>& out) const {
  for (int n = g; goal_tree_[n].parent >= 0; n = goal_tree_[n].parent) {
    out.push_back(goal_tree_[n].edge);
  }
}

// Joins a candidate plan (validated tree edges and a new connection) and validates it as a
// whole, in one call: the trajectory returned is exactly the one checked. The coarse-to-fine
// validator finds a colliding connection about as fast as if it were checked alone.
bool TreeSearch::acceptSolution(std::vector<PathSegment> segments) {
  Trajectory traj = joinSegments(segments, robot_);
  if (traj.empty()) traj.points.push_back({0.0, start_, {}});
  if (!validator_.isValid(traj)) return false;
  result_.trajectory = std::move(traj);
  solution_ = std::move(segments);
  if (!solved_) {
    solved_ = true;
    result_.stats.first_solution_s = elapsed();
    result_.stats.first_solution_iteration = iteration_;
  }
  recordCost(trajectoryCost(result_.trajectory, robot_, weights_));
  return true;
}

// RRT*: the plan of the cheapest goal leaf whose joined trajectory validates as a whole.
bool TreeSearch::extractBestLeaf() {
  std::vector<int> leaves;
  for (int i = 0; i < start_tree_.size(); ++i) {
    if (start_tree_[i].goal_leaf) leaves.push_back(i);
  }
  std::sort(leaves.begin(), leaves.end(), [&](int a, int b) {
    return start_tree_[a].cost < start_tree_[b].cost ||
           (start_tree_[a].cost == start_tree_[b].cost && a < b);
  });
  const double recorded = best_cost_;
  for (int leaf : leaves) {
    std::vector<PathSegment> plan = startPath(leaf);
    Trajectory traj = joinSegments(plan, robot_);
    if (traj.empty()) traj.points.push_back({0.0, start_, {}});
    if (!validator_.isValid(traj)) continue;
    result_.trajectory = std::move(traj);
    solution_ = std::move(plan);
    // Only if the edge-by-edge checks and the whole check disagreed is this worse than the
    // recorded best; the history then says so honestly.
    if (start_tree_[leaf].cost > recorded + kCostEpsilonM) recordCost(start_tree_[leaf].cost);
    return true;
  }
  return false;
}

void TreeSearch::smoothSolution() {
  PhaseTimer timer(result_.stats.times.smoothing_s);
  // The last edge steers to the goal root its end is nearest to.
  const Pose2& end = result_.trajectory.points.back().pose;
  int root = roots_[0];
  for (int r : roots_) {
    if (goal_tree_.distance(end, goal_tree_[r].pose) <
        goal_tree_.distance(end, goal_tree_[root].pose)) {
      root = r;
    }
  }
  const ShortcutSmoother smoother(robot_, steering_, validator_, weights_);
  SmoothingStats stats;
  std::vector<PathSegment> smoothed =
      smoother.smooth(solution_, goal_tree_[root].pose, def_.smoothing_attempts, rng_, &stats);
  result_.stats.smoothing_shortcuts = stats.accepted;
  if (stats.accepted == 0) return;
  Trajectory traj = joinSegments(smoothed, robot_);
  const double cost = trajectoryCost(traj, robot_, weights_);
  if (!(cost < result_.cost_history.back().cost - kCostEpsilonM) || !validator_.isValid(traj)) {
    return;
  }
  result_.trajectory = std::move(traj);
  solution_ = std::move(smoothed);
  recordCost(cost);
}

}  // namespace parksim::detail
