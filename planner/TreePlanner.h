#pragma once
// One sampling-based tree planner; the study's RRT variants are options of it, not copies.
// - kRrt (study 2(e)): grow the tree with fixed-horizon steering; whenever a new node lies
//   within connect_radius_m of the goal (SE(2) metric), try a to-goal trajectory from it.
// - kRrtGoalConnect (study 2(f)): try a to-goal trajectory from every new node.
// In both, a to-goal trajectory ends the search only if the motion validator accepts it, and the
// returned trajectory is the concatenation of exactly the edges that were validated.

#include <cstdint>
#include <string>
#include <vector>

#include "core/Pose2.h"
#include "core/RobotDef.h"
#include "core/Scenario.h"
#include "core/Trajectory.h"
#include "planner/MotionValidator.h"
#include "planner/SteeringFunction.h"

namespace parksim {

enum class PlannerKind { kRrt, kRrtGoalConnect };

const char* toString(PlannerKind kind);
/// Every planner kind, in a fixed order (for benchmarks and help texts).
std::vector<PlannerKind> allPlannerKinds();
/// Parses "rrt" or "rrt-goal-connect"; throws Error otherwise.
PlannerKind plannerKindFromString(const std::string& name);

struct PlannerDef {
  PlannerKind kind = PlannerKind::kRrtGoalConnect;
  std::uint64_t seed = 1;         ///< seeds the planner's own RNG (std::mt19937_64)
  int max_iterations = 2000;      ///< iteration budget (the study's max_step)
  double goal_bias = 0.05;        ///< probability of sampling the goal pose instead of a random one
  double connect_radius_m = 0.1;  ///< kRrt: SE(2) distance to the goal that triggers a to-goal try
  /// Length that turns heading into distance in the SE(2) metric, m: poses are embedded as
  /// (x, y, l cos theta, l sin theta). 0 selects the footprint radius, so a heading change moves
  /// the metric by the chord the farthest footprint corner travels.
  double heading_length_m = 0.0;
  /// Wall-time budget, s; 0 = none. For benchmarks only: results then depend on machine load,
  /// so tests and reproducible runs use max_iterations alone.
  double max_time_s = 0.0;
  bool record_tree = true;  ///< keep every tree edge in the result (for figures)
};

enum class PlanStatus {
  kSolved,
  kIterationLimit,  ///< no valid trajectory to the goal within max_iterations
  kTimeLimit,       ///< no valid trajectory to the goal within max_time_s
  kInvalidStart,    ///< the start footprint collides
  kInvalidGoal,     ///< the goal footprint collides
};

const char* toString(PlanStatus status);

/// Wall time spent in each phase of the search (the study's 3(b) cost breakdown), s.
struct PhaseTimes {
  double sampling_s = 0.0;
  double nearest_s = 0.0;
  double steering_s = 0.0;
  double collision_s = 0.0;   ///< validating tree edges
  double goal_check_s = 0.0;  ///< steering and validating to-goal trajectories
  double total_s = 0.0;
};

struct PlanStats {
  int iterations = 0;
  int tree_size = 0;               ///< nodes, including the start
  int goal_attempts = 0;           ///< to-goal trajectories tried
  long collision_queries = 0;      ///< footprint queries
  double first_solution_s = -1.0;  ///< wall time to the first solution, s; -1 if none
  PhaseTimes times;
};

struct PlanResult {
  PlanStatus status = PlanStatus::kIterationLimit;
  std::string message;                 ///< one line: why it failed, or a summary when solved
  Trajectory trajectory;               ///< start to goal, exactly as validated; empty unless solved
  std::vector<Pose2> waypoints;        ///< tree nodes along the solution, start first
  std::vector<Trajectory> tree_edges;  ///< every edge added to the tree, if recorded
  PlanStats stats;

  bool solved() const { return status == PlanStatus::kSolved; }
};

class TreePlanner {
 public:
  TreePlanner(const RobotDef& robot, const LotBounds& lot, const SteeringFunction& steering,
              const MotionValidator& validator, const PlannerDef& def);

  PlanResult solve(const Pose2& start, const GoalRegion& goal) const;

 private:
  RobotDef robot_;
  LotBounds lot_;
  const SteeringFunction& steering_;
  const MotionValidator& validator_;
  PlannerDef def_;
};

}  // namespace parksim
