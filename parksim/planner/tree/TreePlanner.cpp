#include "parksim/planner/tree/TreePlanner.h"

#include <algorithm>
#include <cmath>

#include "parksim/core/io/Error.h"
#include "parksim/core/model/Geometry.h"
#include "parksim/planner/tree/TreeSearch.h"

namespace parksim {

namespace detail {

Pose2 TreeSearch::sample(bool toward_start) {
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
Pose2 TreeSearch::propose(const Pose2& from, const Pose2& toward) const {
  const double d = start_tree_.distance(from, toward);
  if (d <= def_.extend_distance_m) return {toward.x, toward.y, wrapAngle(toward.theta)};
  const double f = def_.extend_distance_m / d;
  return {from.x + f * (toward.x - from.x), from.y + f * (toward.y - from.y),
          wrapAngle(from.theta + f * angleDiff(toward.theta, from.theta))};
}

void TreeSearch::recordCost(double cost) {
  result_.cost_history.push_back({elapsed(), iteration_, cost});
}

PlanResult TreeSearch::finish(PlanStatus status, std::string message) {
  result_.status = status;
  result_.message = std::move(message);
  result_.stats.collision_queries = validator_.queries() - queries_before_;
  result_.stats.tree_size = start_tree_.size();
  result_.stats.goal_tree_size = goal_tree_.size();
  result_.stats.times.total_s = elapsed();
  return std::move(result_);
}

PlanResult TreeSearch::run(const PlanProgress& progress) {
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
    if ((def_.max_time_s > 0.0 && elapsed() > def_.max_time_s) || def_.cancelled()) {
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
    if (timed_out && def_.cancelled()) {
      return finish(PlanStatus::kCancelled,
                    "cancelled before a collision-free trajectory to "
                    "the goal was found");
    }
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

}  // namespace detail

TreePlannerDef resolvedTreeDef(const TreePlannerDef& def, const RobotDef& robot) {
  TreePlannerDef resolved = def;
  const double scale = robot.sizeScale();  // exactly 1 for the study's robot
  if (resolved.connect_radius_m == 0.0) resolved.connect_radius_m = kStudyConnectRadius_m * scale;
  if (resolved.extend_distance_m == 0.0) {
    resolved.extend_distance_m = kStudyExtendDistance_m * scale;
  }
  return resolved;
}

TreePlanner::TreePlanner(const RobotDef& robot, const LotBounds& lot,
                         const SteeringFunction& steering, const MotionValidator& validator,
                         const TreePlannerDef& requested)
    : robot_(robot),
      lot_(lot),
      steering_(steering),
      validator_(validator),
      def_(resolvedTreeDef(requested, robot)) {
  const TreePlannerDef& def = def_;
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
  return detail::TreeSearch(robot_, lot_, steering_, validator_, def_, start, goal).run(progress);
}

}  // namespace parksim
