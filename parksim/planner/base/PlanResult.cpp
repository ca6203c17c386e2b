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

std::vector<std::pair<const char*, double>> phaseTimeList(const PhaseTimes& t) {
  return {{"sampling", t.sampling_s},      {"nearest_neighbour", t.nearest_s},
          {"steering", t.steering_s},      {"collision_checking", t.collision_s},
          {"goal_checks", t.goal_check_s}, {"rewiring", t.rewiring_s},
          {"connection", t.connection_s},  {"smoothing", t.smoothing_s},
          {"heuristic", t.heuristic_s},    {"timing", t.timing_s}};
}

const char* toString(PlanObjective objective) {
  switch (objective) {
    case PlanObjective::kPathCost: return "path_cost";
    case PlanObjective::kDuration: return "duration";
  }
  return "?";
}

}  // namespace parksim
