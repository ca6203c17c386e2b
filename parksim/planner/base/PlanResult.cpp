#include "parksim/planner/base/PlanResult.h"

namespace parksim {

const char* toString(PlanStatus status) {
  switch (status) {
    case PlanStatus::kSolved: return "solved";
    case PlanStatus::kIterationLimit: return "iteration_limit";
    case PlanStatus::kTimeLimit: return "time_limit";
    case PlanStatus::kInvalidStart: return "invalid_start";
    case PlanStatus::kInvalidGoal: return "invalid_goal";
    case PlanStatus::kCancelled: return "cancelled";
    case PlanStatus::kPlanInvalid: return "plan_invalid";
  }
  return "?";
}

const char* toString(PlanObjective objective) {
  switch (objective) {
    case PlanObjective::kPathCost: return "path_cost";
    case PlanObjective::kDuration: return "duration";
  }
  return "?";
}

}  // namespace parksim
