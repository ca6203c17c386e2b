#pragma once
// Which planner: the names `plan`, `run`, `bench` and sweep specs accept.

#include <string>
#include <vector>

namespace parksim {

/// The planner list: every planner `plan`, `run` and `bench` accept (the tree planner's
/// variants, Hybrid A* with Reeds-Shepp curves, HybridAStar.h, and Hybrid A* in time, the
/// default, TimeAStar.h).
enum class PlannerKind { kRrt, kRrtGoalConnect, kRrtStar, kRrtConnect, kHybridAStar, kTimeAStar };

const char* toString(PlannerKind kind);
/// Every planner kind, in a fixed order (for benchmarks and help texts).
std::vector<PlannerKind> allPlannerKinds();
/// Whether the planner connects poses with the setup's steering function (the tree planners);
/// the A* planners have their own moves and ignore it.
bool plannerUsesSteering(PlannerKind kind);
/// Parses "rrt", "rrt-goal-connect", "rrt-star", "rrt-connect", "hybrid-a-star" or
/// "time-a-star"; throws Error otherwise.
PlannerKind plannerKindFromString(const std::string& name);

}  // namespace parksim
