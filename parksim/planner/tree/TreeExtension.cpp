#include "parksim/planner/tree/TreeSearch.h"

#include <algorithm>
#include <cmath>

#include "parksim/core/model/Geometry.h"

namespace parksim::detail {

// A start-tree node at the end of `edge`, steered from node `parent`, with its cost.
Node TreeSearch::childOf(int parent, SteerResult edge, bool from_rest) const {
  const Node& p = start_tree_[parent];
  const auto& pts = edge.trajectory.points;
  Node n;
  n.pose = pts.back().pose;
  n.arrival = pts.size() >= 2 ? pts[pts.size() - 2].wheels : WheelSpeeds{};
  n.parent = parent;
  n.motion = summarizeMotion(edge.trajectory, robot_);
  n.cost = p.cost + motionCost(n.motion, weights_) +
           weights_.cusp_penalty_m * junctionCusps(p.last_direction, n.motion.first_direction);
  n.last_direction = lastDirectionAfter(p.last_direction, n.motion);
  n.edge = {std::move(edge.trajectory), from_rest};
  return n;
}

// RRT: steer from the nearest node toward the target for a fixed horizon.
int TreeSearch::extendStart(const Pose2& target) {
  PlanStats& st = result_.stats;
  int near;
  {
    PhaseTimer timer(st.times.nearest_s);
    near = start_tree_.nearest(target);
  }
  SteerResult grown;
  {
    PhaseTimer timer(st.times.steering_s);
    const Node& n = start_tree_[near];
    grown = steering_.steer(n.pose, n.arrival, target, SteerMode::kFixedHorizon);
  }
  if (grown.trajectory.points.size() < 2) return -1;  // already at the target
  {
    PhaseTimer timer(st.times.collision_s);
    if (!validator_.isValid(grown.trajectory)) return -1;
  }
  const bool from_rest = start_tree_[near].arrival == WheelSpeeds{};
  return start_tree_.add(childOf(near, std::move(grown), from_rest), true);
}

// RRT*: propose a pose toward the target, connect it from its cheapest valid neighbour, then
// offer it as a cheaper parent to the other neighbours.
int TreeSearch::extendOptimal(const Pose2& target) {
  PlanStats& st = result_.stats;
  int near;
  std::vector<int> neighbours;
  Pose2 x;
  {
    PhaseTimer timer(st.times.nearest_s);
    near = start_tree_.nearest(target);
  }
  {
    PhaseTimer timer(st.times.steering_s);
    x = propose(start_tree_[near].pose, target);
  }
  {
    PhaseTimer timer(st.times.collision_s);
    if (!validator_.isValid(x)) return -1;
  }
  {
    PhaseTimer timer(st.times.nearest_s);
    if (def_.rewire_radius_m > 0.0) {
      neighbours = start_tree_.withinRadius(x, def_.rewire_radius_m);
    } else {
      const double n = static_cast<double>(start_tree_.indexedCount() + 1);
      const auto k = def_.rewire_neighbours > 0
                         ? static_cast<std::size_t>(def_.rewire_neighbours)
                         : static_cast<std::size_t>(std::ceil(kRrtStarK * std::log(n)));
      neighbours = start_tree_.kNearest(x, std::max<std::size_t>(k, 1));
    }
    if (std::find(neighbours.begin(), neighbours.end(), near) == neighbours.end()) {
      neighbours.push_back(near);
    }
  }

  PhaseTimer timer(st.times.rewiring_s);
  // Choose the parent lazily, best first: steer from neighbours in order of a lower bound on
  // the cost through them (straight-line distance), validate the cheapest steered candidate,
  // and steer more only while a neighbour's bound beats the cheapest candidate left.
  struct Candidate {
    double cost;
    int parent;
    SteerResult edge;
  };
  auto bound = [&](int id) {
    return start_tree_[id].cost + positionDistance(start_tree_[id].pose, x);
  };
  std::sort(neighbours.begin(), neighbours.end(),
            [&](int a, int b) { return bound(a) < bound(b) || (bound(a) == bound(b) && a < b); });
  std::vector<Candidate> heap;
  auto cheaper = [](const Candidate& a, const Candidate& b) {
    return a.cost > b.cost || (a.cost == b.cost && a.parent > b.parent);
  };
  std::size_t next = 0;
  int id = -1;
  while (id < 0) {
    while (next < neighbours.size() &&
           (heap.empty() || bound(neighbours[next]) < heap.front().cost)) {
      const int p = neighbours[next++];
      const Node& pn = start_tree_[p];
      SteerResult edge = steering_.steer(pn.pose, {}, x, SteerMode::kExact);
      if (!edge.reached || edge.trajectory.points.size() < 2) continue;
      const MotionSummary m = summarizeMotion(edge.trajectory, robot_);
      const double cost =
          pn.cost + motionCost(m, weights_) +
          weights_.cusp_penalty_m * junctionCusps(pn.last_direction, m.first_direction);
      heap.push_back({cost, p, std::move(edge)});
      std::push_heap(heap.begin(), heap.end(), cheaper);
    }
    if (heap.empty()) return -1;
    std::pop_heap(heap.begin(), heap.end(), cheaper);
    Candidate c = std::move(heap.back());
    heap.pop_back();
    if (!validator_.isValid(c.edge.trajectory)) continue;
    id = start_tree_.add(childOf(c.parent, std::move(c.edge), true), true);
  }
  rewireAround(id, neighbours);
  return id;
}

void TreeSearch::rewireAround(int id, const std::vector<int>& neighbours) {
  const Pose2 x = start_tree_[id].pose;
  for (int q : neighbours) {
    const Node& xn = start_tree_[id];
    const Node& qn = start_tree_[q];
    if (q == xn.parent || qn.parent < 0) continue;
    if (xn.cost + positionDistance(x, qn.pose) >= qn.cost - kCostEpsilonM) continue;
    SteerResult edge = steering_.steer(x, {}, qn.pose, SteerMode::kExact);
    if (!edge.reached || edge.trajectory.points.size() < 2) continue;
    const MotionSummary m = summarizeMotion(edge.trajectory, robot_);
    const double cost =
        xn.cost + motionCost(m, weights_) +
        weights_.cusp_penalty_m * junctionCusps(xn.last_direction, m.first_direction);
    if (cost >= qn.cost - kCostEpsilonM) continue;
    // Descendants count their cusps from q's last direction; keep it so each of their costs
    // drops by exactly as much as q's.
    const int last = lastDirectionAfter(xn.last_direction, m);
    if (!qn.children.empty() && last != qn.last_direction) continue;
    if (!validator_.isValid(edge.trajectory)) continue;

    std::vector<int>& siblings = start_tree_[qn.parent].children;
    siblings.erase(std::find(siblings.begin(), siblings.end(), q));
    start_tree_[id].children.push_back(q);
    Node& moved = start_tree_[q];
    const double delta = cost - moved.cost;
    moved.parent = id;
    moved.edge = {std::move(edge.trajectory), true};
    moved.motion = m;
    moved.last_direction = last;
    propagateCost(q, delta);
    ++result_.stats.rewires;
  }
}

// Shifts the cost of `id` and its subtree by delta (< 0) and keeps the best goal leaf.
void TreeSearch::propagateCost(int id, double delta) {
  std::vector<int> stack{id};
  int best = -1;
  while (!stack.empty()) {
    Node& n = start_tree_[stack.back()];
    const int current = stack.back();
    stack.pop_back();
    n.cost += delta;
    if (n.goal_leaf && (best < 0 || n.cost < start_tree_[best].cost)) best = current;
    stack.insert(stack.end(), n.children.begin(), n.children.end());
  }
  if (best >= 0 && start_tree_[best].cost < best_cost_ - kCostEpsilonM) {
    best_leaf_ = best;
    best_cost_ = start_tree_[best].cost;
    recordCost(best_cost_);
  }
}

// RRT-Connect: a new goal-tree node toward the target, with an edge steered from it to its
// parent (forward in time, toward the goal).
int TreeSearch::extendGoalTree(const Pose2& target) {
  PlanStats& st = result_.stats;
  int parent;
  {
    PhaseTimer timer(st.times.nearest_s);
    parent = goal_tree_.nearest(target);
  }
  const Node& p = goal_tree_[parent];
  Pose2 c;
  SteerResult edge;
  {
    PhaseTimer timer(st.times.steering_s);
    c = propose(p.pose, target);
    // Into a root the edge only has to end within the goal tolerance: that is where plans end.
    edge = steering_.steer(c, {}, p.pose, p.parent < 0 ? SteerMode::kToGoal : SteerMode::kExact);
  }
  if (!edge.reached || edge.trajectory.points.size() < 2) return -1;
  {
    PhaseTimer timer(st.times.collision_s);
    if (!validator_.isValid(edge.trajectory)) return -1;
  }
  Node n;
  n.pose = c;
  n.parent = parent;
  n.motion = summarizeMotion(edge.trajectory, robot_);
  n.edge = {std::move(edge.trajectory), true};
  return goal_tree_.add(std::move(n), true);
}

}  // namespace parksim::detail
