#include "parksim/planner/PlannerKind.h"

#include "parksim/core/Error.h"

namespace parksim {

const char* toString(PlannerKind kind) {
  switch (kind) {
    case PlannerKind::kRrt: return "rrt";
    case PlannerKind::kRrtGoalConnect: return "rrt-goal-connect";
    case PlannerKind::kRrtStar: return "rrt-star";
    case PlannerKind::kRrtConnect: return "rrt-connect";
    case PlannerKind::kHybridAStar: return "hybrid-a-star";
    case PlannerKind::kTimeAStar: return "time-a-star";
  }
  return "?";
}

std::vector<PlannerKind> allPlannerKinds() {
  return {PlannerKind::kRrt,        PlannerKind::kRrtGoalConnect, PlannerKind::kRrtStar,
          PlannerKind::kRrtConnect, PlannerKind::kHybridAStar,    PlannerKind::kTimeAStar};
}

bool plannerUsesSteering(PlannerKind kind) {
  return kind != PlannerKind::kHybridAStar && kind != PlannerKind::kTimeAStar;
}

PlannerKind plannerKindFromString(const std::string& name) {
  std::string known;
  for (PlannerKind k : allPlannerKinds()) {
    if (name == toString(k)) return k;
    known += (known.empty() ? "" : ", ") + std::string(toString(k));
  }
  throw Error("unknown planner '" + name + "' (expected one of " + known + ")");
}

}  // namespace parksim
