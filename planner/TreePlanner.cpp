#include "planner/TreePlanner.h"

#include <chrono>
#include <cmath>
#include <random>

#include "core/Error.h"
#include "core/Geometry.h"
#include "planner/NearestNeighbors.h"

namespace parksim {

const char* toString(PlannerKind kind) {
  switch (kind) {
    case PlannerKind::kRrt: return "rrt";
    case PlannerKind::kRrtGoalConnect: return "rrt-goal-connect";
  }
  return "?";
}

std::vector<PlannerKind> allPlannerKinds() {
  return {PlannerKind::kRrt, PlannerKind::kRrtGoalConnect};
}

PlannerKind plannerKindFromString(const std::string& name) {
  for (PlannerKind k : allPlannerKinds()) {
    if (name == toString(k)) return k;
  }
  throw Error("unknown planner '" + name + "' (expected rrt or rrt-goal-connect)");
}

const char* toString(PlanStatus status) {
  switch (status) {
    case PlanStatus::kSolved: return "solved";
    case PlanStatus::kIterationLimit: return "iteration_limit";
    case PlanStatus::kTimeLimit: return "time_limit";
    case PlanStatus::kInvalidStart: return "invalid_start";
    case PlanStatus::kInvalidGoal: return "invalid_goal";
  }
  return "?";
}

namespace {

using Clock = std::chrono::steady_clock;

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

struct Node {
  Pose2 pose;
  WheelSpeeds arrival;  // wheel speeds on arrival, where the next edge's acceleration starts
  int parent = -1;
  int edge = -1;  // index of the edge from the parent
};

}  // namespace

TreePlanner::TreePlanner(const RobotDef& robot, const LotBounds& lot,
                         const SteeringFunction& steering, const MotionValidator& validator,
                         const PlannerDef& def)
    : robot_(robot), lot_(lot), steering_(steering), validator_(validator), def_(def) {
  if (def.max_iterations < 0) throw Error("planner: max_iterations must be >= 0");
  if (!(def.goal_bias >= 0.0 && def.goal_bias <= 1.0)) {
    throw Error("planner: goal_bias must be in [0, 1]");
  }
  if (!(def.connect_radius_m >= 0.0) || !(def.heading_length_m >= 0.0)) {
    throw Error("planner: connect_radius_m and heading_length_m must be >= 0");
  }
}

PlanResult TreePlanner::solve(const Pose2& start, const GoalRegion& goal) const {
  const Clock::time_point t_begin = Clock::now();
  const long queries_before = validator_.queries();
  PlanResult result;
  PhaseTimes& times = result.stats.times;
  auto finish = [&](PlanStatus status, std::string message) {
    result.status = status;
    result.message = std::move(message);
    result.stats.collision_queries = validator_.queries() - queries_before;
    times.total_s = std::chrono::duration<double>(Clock::now() - t_begin).count();
    return result;
  };

  if (!validator_.isValid(start)) return finish(PlanStatus::kInvalidStart, "start pose collides");
  if (!validator_.isValid(goal.pose)) return finish(PlanStatus::kInvalidGoal, "goal pose collides");

  std::mt19937_64 rng(def_.seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double l = def_.heading_length_m > 0.0 ? def_.heading_length_m : footprintRadius(robot_);
  NearestNeighbors nn(l);
  std::vector<Node> nodes;
  std::vector<Trajectory> edges;
  nodes.push_back({start, {}, -1, -1});
  nn.add(start);

  // Tries the to-goal trajectory from node `from`; on success stores the solution.
  auto tryGoal = [&](int from) {
    PhaseTimer timer(times.goal_check_s);
    ++result.stats.goal_attempts;
    SteerResult to_goal =
        steering_.steer(nodes[from].pose, nodes[from].arrival, goal.pose, SteerMode::kToGoal);
    if (!to_goal.reached || !validator_.isValid(to_goal.trajectory)) return false;
    std::vector<int> chain;
    for (int n = from; n >= 0; n = nodes[n].parent) chain.push_back(n);
    for (auto it = chain.rbegin(); it != chain.rend(); ++it) {
      result.waypoints.push_back(nodes[*it].pose);
      if (nodes[*it].edge >= 0) result.trajectory.append(edges[nodes[*it].edge]);
    }
    if (result.trajectory.empty()) result.trajectory.points.push_back({0.0, start, {}});
    result.trajectory.append(to_goal.trajectory);
    result.waypoints.push_back(to_goal.trajectory.points.back().pose);
    result.stats.first_solution_s = std::chrono::duration<double>(Clock::now() - t_begin).count();
    return true;
  };

  auto wantsGoalTry = [&](int node) {
    return def_.kind == PlannerKind::kRrtGoalConnect ||
           nn.distance(nodes[node].pose, goal.pose) <= def_.connect_radius_m;
  };

  bool solved = wantsGoalTry(0) && tryGoal(0);
  auto outOfTime = [&] {
    return def_.max_time_s > 0.0 &&
           std::chrono::duration<double>(Clock::now() - t_begin).count() > def_.max_time_s;
  };
  bool timed_out = false;
  int it = 0;
  for (; !solved && it < def_.max_iterations; ++it) {
    if (outOfTime()) {
      timed_out = true;
      break;
    }
    Pose2 sample;
    {
      PhaseTimer timer(times.sampling_s);
      if (unit(rng) < def_.goal_bias) {
        sample = goal.pose;
      } else {
        sample.x = lot_.x_min_m + unit(rng) * (lot_.x_max_m - lot_.x_min_m);
        sample.y = lot_.y_min_m + unit(rng) * (lot_.y_max_m - lot_.y_min_m);
        sample.theta = -kPi + unit(rng) * 2.0 * kPi;
      }
    }
    int near;
    {
      PhaseTimer timer(times.nearest_s);
      near = static_cast<int>(nn.nearest(sample));
    }
    SteerResult grown;
    {
      PhaseTimer timer(times.steering_s);
      grown =
          steering_.steer(nodes[near].pose, nodes[near].arrival, sample, SteerMode::kFixedHorizon);
    }
    if (grown.trajectory.points.size() < 2) continue;  // already at the sample
    {
      PhaseTimer timer(times.collision_s);
      if (!validator_.isValid(grown.trajectory)) continue;
    }
    const auto& pts = grown.trajectory.points;
    const int id = static_cast<int>(nodes.size());
    nodes.push_back(
        {pts.back().pose, pts[pts.size() - 2].wheels, near, static_cast<int>(edges.size())});
    edges.push_back(std::move(grown.trajectory));
    nn.add(nodes.back().pose);
    solved = wantsGoalTry(id) && tryGoal(id);
  }

  result.stats.iterations = it;
  result.stats.tree_size = static_cast<int>(nodes.size());
  if (def_.record_tree) result.tree_edges = std::move(edges);
  if (!solved && timed_out) {
    return finish(PlanStatus::kTimeLimit, "no collision-free trajectory to the goal within " +
                                              std::to_string(def_.max_time_s) + " s");
  }
  if (!solved) {
    return finish(PlanStatus::kIterationLimit, "no collision-free trajectory to the goal within " +
                                                   std::to_string(def_.max_iterations) +
                                                   " iterations");
  }
  return finish(PlanStatus::kSolved, "solved");
}

}  // namespace parksim
