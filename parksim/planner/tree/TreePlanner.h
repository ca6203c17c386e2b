#pragma once
// One sampling-based tree planner; the variants are options of its loop, not copies.
//
// The start tree grows from the start; the goal side is a goal tree whose roots are the goal
// pose (and the goal pose turned by pi when the goal accepts either heading). Each iteration
// samples, extends a tree, and tries to connect the new node to the other side:
// - kRrt (study 2(e)): the start tree grows with fixed-horizon steering; a new node within
//   connect_radius_m of a goal root (SE(2) metric) tries a to-goal trajectory to it.
// - kRrtGoalConnect (study 2(f)): every new node tries a to-goal trajectory.
// - kRrtConnect: the goal tree grows too, on alternate iterations. Its edges run forward in
//   time from the new (child) node to its parent, toward the goal: each is steered from the
//   child, never a start-tree trajectory played backwards. New nodes of either tree try to
//   connect to the nearest node of the other.
// - kRrtStar: start-tree nodes are rest poses joined by rest-to-rest edges steered in kExact
//   mode, so the tree can be rewired: a new node picks the cheapest valid parent among its
//   neighbours, then becomes the parent of neighbours it reaches more cheaply. The cost is path
//   length plus penalties for reversing and cusps (PathCost.h). Anytime: it keeps improving
//   until max_iterations (or max_time_s) and records each improvement in cost_history. With
//   informed_sampling it is Informed RRT*: once solved, it samples only where a cheaper path
//   could pass.
// Any of them may be followed by shortcut smoothing (ShortcutSmoother.h: `smooth`, with the
// study's timing; with time-optimal timing the registered planners smooth along the plan's
// geometry instead, PlanFinishing.h).
//
// Exact junctions. Start-tree edges start at their parent's pose with the parent's arrival
// wheel speeds, and a node's pose is the exact end of its edge. Edges into nodes that other
// edges already leave (rewired RRT* nodes, goal-tree nodes, connections to goal-tree nodes) are
// steered in kExact mode and end exactly at the node, at rest; the edges leaving such nodes are
// steered from rest, and where the wheel speeds would jump at a junction the robot stands still
// for one period (PathSegment.h). Only the last edge, into a goal root, ends within the goal
// tolerance. A candidate solution (tree edges plus the new connection) is joined first and
// validated as a whole, so the trajectory returned is exactly the one checked; RRT* validates
// its best plan as a whole once more at the end, and smoothing its result.

#include <cstdint>
#include <string>
#include <vector>

#include "parksim/core/geometry/Pose2.h"
#include "parksim/core/model/RobotDef.h"
#include "parksim/core/model/Scenario.h"
#include "parksim/core/model/Trajectory.h"
#include "parksim/planner/base/PlanResult.h"
#include "parksim/planner/base/SearchDef.h"
#include "parksim/planner/motion/MotionValidator.h"
#include "parksim/planner/motion/PathCost.h"
#include "parksim/planner/motion/SteeringFunction.h"

namespace parksim {

/// The tree planner's variants (the comment above); registered as "rrt", "rrt-goal-connect",
/// "rrt-star" and "rrt-connect" (TreePlanners.cpp).
enum class TreeVariant { kRrt, kRrtGoalConnect, kRrtStar, kRrtConnect };

/// TreePlannerDef's lengths for the study's robot, m: a robot of another size gets them in
/// proportion (RobotDef::sizeScale) when its Def leaves them 0.
inline constexpr double kStudyConnectRadius_m = 0.1;
inline constexpr double kStudyExtendDistance_m = 0.15;

/// The tree planner's own parameters, on top of the search settings every planner shares.
struct TreePlannerDef : SearchDef {
  TreeVariant variant = TreeVariant::kRrtGoalConnect;
  double goal_bias = 0.05;  ///< probability of sampling a goal pose instead of a random one
  /// kRrt: SE(2) distance to the goal that triggers a to-goal try, m; 0: 0.1 m for the study's
  /// robot, in proportion to the robot's size.
  double connect_radius_m = 0.0;
  /// Length that turns heading into distance in the SE(2) metric, m: poses are embedded as
  /// (x, y, l cos theta, l sin theta). 0 selects the footprint radius, so a heading change moves
  /// the metric by the chord the farthest footprint corner travels.
  double heading_length_m = 0.0;

  /// kRrtStar and the goal tree of kRrtConnect: a new node lies at most this far (SE(2) metric)
  /// from the tree node nearest to its sample, m; 0: 0.15 m for the study's robot, in
  /// proportion to the robot's size.
  double extend_distance_m = 0.0;
  /// kRrtStar: number of nearest neighbours considered as parents and for rewiring; 0 selects
  /// k = ceil(e (1 + 1/3) ln n), the usual k-nearest RRT* rule for a 3-dimensional space.
  int rewire_neighbours = 0;
  /// kRrtStar: when > 0, use every node within this SE(2) distance instead of k-nearest, m.
  double rewire_radius_m = 0.0;
  /// kRrtStar, once solved: sample only positions whose straight-line distance from the start
  /// plus to the goal is below the best cost (Informed RRT*'s ellipse; no path through the
  /// others can be cheaper, since the cost is at least the length).
  bool informed_sampling = true;
};

/// `def` with its automatic lengths (connect_radius_m, extend_distance_m) made for `robot`.
TreePlannerDef resolvedTreeDef(const TreePlannerDef& def, const RobotDef& robot);

class TreePlanner {
 public:
  TreePlanner(const RobotDef& robot, const LotBounds& lot, const SteeringFunction& steering,
              const MotionValidator& validator, const TreePlannerDef& def);

  /// `progress`, when set, is told of every iteration.
  PlanResult solve(const Pose2& start, const GoalRegion& goal,
                   const PlanProgress& progress = {}) const;

 private:
  RobotDef robot_;
  LotBounds lot_;
  const SteeringFunction& steering_;
  const MotionValidator& validator_;
  TreePlannerDef def_;
};

}  // namespace parksim
