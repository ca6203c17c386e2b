#include "parksim/planner/TreePlanner.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>
#include <random>

#include "parksim/core/Error.h"
#include "parksim/core/Geometry.h"
#include "parksim/planner/NearestNeighbors.h"
#include "parksim/planner/PathSegment.h"
#include "parksim/planner/SearchTree.h"
#include "parksim/planner/ShortcutSmoother.h"

namespace parksim {

namespace {

using Clock = std::chrono::steady_clock;
using detail::Node;
using detail::Tree;

// Below this a cost difference is rounding, not an improvement, m.
constexpr double kCostEpsilonM = 1e-9;
// k-nearest RRT*: k = e (1 + 1/d) ln n keeps asymptotic optimality; d = 3 for SE(2).
constexpr double kRrtStarK = std::numbers::e * (1.0 + 1.0 / 3.0);
// Informed sampling gives up looking for a sample inside the ellipse after this many.
constexpr int kInformedSampleTries = 100;

// Adds the time since construction to a phase total when it goes out of scope.
class PhaseTimer {
 public:
  explicit PhaseTimer(double& total) : total_(total), start_(Clock::now()) {}
  ~PhaseTimer() { total_ += std::chrono::duration<double>(Clock::now() - start_).count(); }
  PhaseTimer(const PhaseTimer&) = delete;
  PhaseTimer& operator=(const PhaseTimer&) = delete;

 private:
  double& total_;
  Clock::time_point start_;
};

// One call of TreePlanner::solve: the trees, the RNG and the result being built.
class Search {
 public:
  Search(const RobotDef& robot, const LotBounds& lot, const SteeringFunction& steering,
         const MotionValidator& validator, const PlannerDef& def, const Pose2& start,
         const GoalRegion& goal)
      : robot_(robot),
        lot_(lot),
        steering_(steering),
        validator_(validator),
        def_(def),
        weights_{def.reverse_penalty, def.cusp_penalty_m},
        start_(start),
        goal_(goal),
        rng_(def.seed),
        start_tree_(headingLength()),
        goal_tree_(headingLength()),
        bidirectional_(def.kind == PlannerKind::kRrtConnect),
        optimize_(def.kind == PlannerKind::kRrtStar),
        t_begin_(Clock::now()) {}

  PlanResult run(const PlanProgress& progress);

 private:
  double headingLength() const {
    return def_.heading_length_m > 0.0 ? def_.heading_length_m : footprintRadius(robot_);
  }
  double elapsed() const { return std::chrono::duration<double>(Clock::now() - t_begin_).count(); }
  double unit() { return std::uniform_real_distribution<double>(0.0, 1.0)(rng_); }

  Pose2 sample(bool toward_start);
  Pose2 propose(const Pose2& from, const Pose2& toward) const;
  Node childOf(int parent, SteerResult edge, bool from_rest) const;

  int extendStart(const Pose2& target);
  int extendOptimal(const Pose2& target);
  int extendGoalTree(const Pose2& target);
  void rewireAround(int id, const std::vector<int>& neighbours);
  void propagateCost(int id, double delta);

  void connectToGoal(int s);
  void connectFromStart(int g);
  void tryGoalLeaves(int s);

  std::vector<PathSegment> startPath(int id) const;
  void appendGoalPath(int g, std::vector<PathSegment>& out) const;
  bool acceptSolution(std::vector<PathSegment> segments);
  bool extractBestLeaf();
  void smoothSolution();
  void recordCost(double cost);
  PlanResult finish(PlanStatus status, std::string message);

  const RobotDef& robot_;
  const LotBounds& lot_;
  const SteeringFunction& steering_;
  const MotionValidator& validator_;
  const PlannerDef& def_;
  const CostWeights weights_;
  const Pose2 start_;
  const GoalRegion goal_;
  std::mt19937_64 rng_;
  Tree start_tree_;
  Tree goal_tree_;  // roots: the accepted goal poses
  std::vector<int> roots_;
  const bool bidirectional_;
  const bool optimize_;
  const Clock::time_point t_begin_;
  long queries_before_ = 0;
  int iteration_ = 0;  // iterations completed, counting the one under way

  bool solved_ = false;
  std::vector<PathSegment> solution_;  // the accepted plan, edge by edge
  int best_leaf_ = -1;                 // kRrtStar: cheapest goal leaf
  double best_cost_ = 0.0;
  PlanResult result_;
};

Pose2 Search::sample(bool toward_start) {
  PhaseTimer timer(result_.stats.times.sampling_s);
  if (unit() < def_.goal_bias) {
    // The goal tree grows toward the start as the start tree grows toward the goal.
    if (toward_start) return start_;
    if (roots_.size() == 1) return goal_tree_[roots_[0]].pose;
    return goal_tree_[roots_[unit() < 0.5 ? 0 : 1]].pose;
  }
  auto uniform = [&] {
    Pose2 s;
    s.x = lot_.x_min_m + unit() * (lot_.x_max_m - lot_.x_min_m);
    s.y = lot_.y_min_m + unit() * (lot_.y_max_m - lot_.y_min_m);
    s.theta = -kPi + unit() * 2.0 * kPi;
    return s;
  };
  if (!(optimize_ && def_.informed_sampling && best_leaf_ >= 0)) return uniform();
  // Informed: rejection-sample the ellipse of positions a cheaper path could pass through.
  // The goal roots share one position. Bounded: after many misses take the last sample.
  const Pose2& goal = goal_tree_[roots_[0]].pose;
  Pose2 s;
  for (int tries = 0; tries < kInformedSampleTries; ++tries) {
    s = uniform();
    if (positionDistance(start_, s) + positionDistance(s, goal) < best_cost_) break;
  }
  return s;
}

// The pose extend_distance_m from `from` toward `toward` (SE(2) interpolation), or `toward`
// itself when it is closer.
Pose2 Search::propose(const Pose2& from, const Pose2& toward) const {
  const double d = start_tree_.distance(from, toward);
  if (d <= def_.extend_distance_m) return {toward.x, toward.y, wrapAngle(toward.theta)};
  const double f = def_.extend_distance_m / d;
  return {from.x + f * (toward.x - from.x), from.y + f * (toward.y - from.y),
          wrapAngle(from.theta + f * angleDiff(toward.theta, from.theta))};
}

// A start-tree node at the end of `edge`, steered from node `parent`, with its cost.
Node Search::childOf(int parent, SteerResult edge, bool from_rest) const {
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
int Search::extendStart(const Pose2& target) {
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
int Search::extendOptimal(const Pose2& target) {
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

void Search::rewireAround(int id, const std::vector<int>& neighbours) {
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
void Search::propagateCost(int id, double delta) {
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
int Search::extendGoalTree(const Pose2& target) {
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

// After start-tree node s was added: try to reach the goal side from it.
void Search::connectToGoal(int s) {
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
  if (def_.kind == PlannerKind::kRrt &&
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
void Search::connectFromStart(int g) {
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
void Search::tryGoalLeaves(int s) {
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

std::vector<PathSegment> Search::startPath(int id) const {
  std::vector<PathSegment> plan;
  for (int n = id; start_tree_[n].parent >= 0; n = start_tree_[n].parent) {
    plan.push_back(start_tree_[n].edge);
  }
  std::reverse(plan.begin(), plan.end());
  return plan;
}

void Search::appendGoalPath(int g, std::vector<PathSegment>& out) const {
  for (int n = g; goal_tree_[n].parent >= 0; n = goal_tree_[n].parent) {
    out.push_back(goal_tree_[n].edge);
  }
}

// Joins a candidate plan (validated tree edges and a new connection) and validates it as a
// whole, in one call: the trajectory returned is exactly the one checked. The coarse-to-fine
// validator finds a colliding connection about as fast as if it were checked alone.
bool Search::acceptSolution(std::vector<PathSegment> segments) {
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
bool Search::extractBestLeaf() {
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

void Search::smoothSolution() {
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

void Search::recordCost(double cost) {
  result_.cost_history.push_back({elapsed(), iteration_, cost});
}

PlanResult Search::finish(PlanStatus status, std::string message) {
  result_.status = status;
  result_.message = std::move(message);
  result_.stats.collision_queries = validator_.queries() - queries_before_;
  result_.stats.tree_size = start_tree_.size();
  result_.stats.goal_tree_size = goal_tree_.size();
  result_.stats.times.total_s = elapsed();
  return std::move(result_);
}

PlanResult Search::run(const PlanProgress& progress) {
  queries_before_ = validator_.queries();
  if (!validator_.isValid(start_)) {
    return finish(PlanStatus::kInvalidStart,
                  validator_.insideLot(start_)
                      ? "start pose collides"
                      : "start pose lies within half the motion-check resolution of the lot edge");
  }
  std::vector<Pose2> goals{goal_.pose};
  if (goal_.either_heading)
    goals.push_back({goal_.pose.x, goal_.pose.y, wrapAngle(goal_.pose.theta + kPi)});
  for (const Pose2& g : goals) {
    if (validator_.isValid(g)) {
      Node root;
      root.pose = g;
      roots_.push_back(goal_tree_.add(std::move(root), true));
    }
  }
  if (roots_.empty()) {
    return finish(PlanStatus::kInvalidGoal,
                  validator_.insideLot(goal_.pose)
                      ? "goal pose collides"
                      : "goal pose lies within half the motion-check resolution of the lot edge");
  }
  Node root;
  root.pose = start_;
  start_tree_.add(std::move(root), true);

  connectToGoal(0);
  bool timed_out = false;
  for (int it = 0; it < def_.max_iterations && (optimize_ || !solved_); ++it) {
    if (def_.max_time_s > 0.0 && elapsed() > def_.max_time_s) {
      timed_out = true;
      break;
    }
    // Solutions found in this iteration count it as completed.
    iteration_ = it + 1;
    // RRT-Connect grows the goal tree on odd iterations, toward samples biased to the start.
    const bool grow_goal = bidirectional_ && it % 2 == 1;
    const Pose2 target = sample(grow_goal);
    if (grow_goal) {
      const int g = extendGoalTree(target);
      if (g >= 0) connectFromStart(g);
    } else {
      const int s = optimize_ ? extendOptimal(target) : extendStart(target);
      if (s >= 0) connectToGoal(s);
    }
    if (progress) progress(iteration_, def_.max_iterations);
  }
  result_.stats.iterations = iteration_;
  if (optimize_ && solved_ && !extractBestLeaf()) {
    // No candidate survived the final whole-path check: nothing was found after all.
    solved_ = false;
    result_.stats.first_solution_s = -1.0;
    result_.stats.first_solution_iteration = -1;
  }

  if (def_.record_tree) {
    for (int i = 0; i < start_tree_.size(); ++i) {
      if (start_tree_[i].parent >= 0) result_.tree_edges.push_back(start_tree_[i].edge.trajectory);
    }
    for (int i = 0; i < goal_tree_.size(); ++i) {
      if (goal_tree_[i].parent >= 0) result_.tree_edges.push_back(goal_tree_[i].edge.trajectory);
    }
  }
  if (!solved_) {
    result_.cost_history.clear();
    if (timed_out) {
      return finish(PlanStatus::kTimeLimit, "no collision-free trajectory to the goal within " +
                                                std::to_string(def_.max_time_s) + " s");
    }
    return finish(PlanStatus::kIterationLimit, "no collision-free trajectory to the goal within " +
                                                   std::to_string(def_.max_iterations) +
                                                   " iterations");
  }
  if (def_.smooth && def_.smoothing_attempts > 0) smoothSolution();
  result_.cost = trajectoryCost(result_.trajectory, robot_, weights_);
  for (const PathSegment& seg : solution_) {
    if (seg.trajectory.points.size() >= 2)
      result_.waypoints.push_back(seg.trajectory.points.front().pose);
  }
  result_.waypoints.push_back(result_.trajectory.points.back().pose);
  return finish(PlanStatus::kSolved, "solved");
}

}  // namespace

TreePlanner::TreePlanner(const RobotDef& robot, const LotBounds& lot,
                         const SteeringFunction& steering, const MotionValidator& validator,
                         const PlannerDef& def)
    : robot_(robot), lot_(lot), steering_(steering), validator_(validator), def_(def) {
  if (def.kind == PlannerKind::kHybridAStar) {
    throw Error("planner: hybrid-a-star is not a tree planner (use HybridAStar)");
  }
  if (def.max_iterations < 0) throw Error("planner: max_iterations must be >= 0");
  if (!(def.goal_bias >= 0.0 && def.goal_bias <= 1.0)) {
    throw Error("planner: goal_bias must be in [0, 1]");
  }
  if (!(def.connect_radius_m >= 0.0) || !(def.heading_length_m >= 0.0)) {
    throw Error("planner: connect_radius_m and heading_length_m must be >= 0");
  }
  if (!(def.reverse_penalty >= 0.0) || !(def.cusp_penalty_m >= 0.0)) {
    throw Error("planner: reverse_penalty and cusp_penalty_m must be >= 0");
  }
  if (!(def.extend_distance_m > 0.0)) throw Error("planner: extend_distance_m must be positive");
  if (def.rewire_neighbours < 0 || !(def.rewire_radius_m >= 0.0)) {
    throw Error("planner: rewire_neighbours and rewire_radius_m must be >= 0");
  }
  if (def.smoothing_attempts < 0) throw Error("planner: smoothing_attempts must be >= 0");
  if (!(def.max_time_s >= 0.0)) throw Error("planner: max_time_s must be >= 0");
}

PlanResult TreePlanner::solve(const Pose2& start, const GoalRegion& goal,
                              const PlanProgress& progress) const {
  return Search(robot_, lot_, steering_, validator_, def_, start, goal).run(progress);
}

}  // namespace parksim
