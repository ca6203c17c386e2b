#pragma once
// Internal to TreePlanner (TreePlanner.h explains the planner): the state of one call of
// TreePlanner::solve, its trees, generator and result. Its member functions live by concept:
// TreePlanner.cpp (the loop, sampling, results), TreeExtension.cpp (growing and rewiring the
// trees), TreeConnection.cpp (connecting the trees and the goal, solutions, smoothing).

#include <chrono>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "parksim/planner/base/PhaseTimer.h"
#include "parksim/planner/tree/PathSegment.h"
#include "parksim/planner/tree/SearchTree.h"
#include "parksim/planner/tree/TreePlanner.h"

namespace parksim::detail {

using Clock = std::chrono::steady_clock;

// Below this a cost difference is rounding, not an improvement, m.
inline constexpr double kCostEpsilonM = 1e-9;
// k-nearest RRT*: k = e (1 + 1/d) ln n keeps asymptotic optimality; d = 3 for SE(2).
inline constexpr double kRrtStarK = std::numbers::e * (1.0 + 1.0 / 3.0);
// Informed sampling gives up looking for a sample inside the ellipse after this many.
inline constexpr int kInformedSampleTries = 100;

// One call of TreePlanner::solve: the trees, the RNG and the result being built.
class TreeSearch {
 public:
  TreeSearch(const RobotDef& robot, const LotBounds& lot, const SteeringFunction& steering,
             const MotionValidator& validator, const TreePlannerDef& def, const Pose2& start,
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
        bidirectional_(def.variant == TreeVariant::kRrtConnect),
        optimize_(def.variant == TreeVariant::kRrtStar),
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
  const TreePlannerDef& def_;
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

}  // namespace parksim::detail
