#include "parksim/planner/PlanScenario.h"

#include <algorithm>
#include <memory>
#include <optional>
#include <string>

#include "parksim/core/Error.h"

namespace parksim {

const char* toString(SteeringKind kind) {
  switch (kind) {
    case SteeringKind::kMoveToPose: return "move-to-pose";
    case SteeringKind::kRotateTranslateRotate: return "rotate-translate-rotate";
  }
  return "?";
}

std::vector<SteeringKind> allSteeringKinds() {
  return {SteeringKind::kMoveToPose, SteeringKind::kRotateTranslateRotate};
}

SteeringKind steeringKindFromString(const std::string& name) {
  std::string known;
  for (SteeringKind k : allSteeringKinds()) {
    if (name == toString(k)) return k;
    known += (known.empty() ? "" : ", ") + std::string(toString(k));
  }
  throw Error("unknown steering '" + name + "' (expected one of " + known + ")");
}

PlanResult planScenario(const Scenario& scenario, const FootprintChecker& checker,
                        const PlanSetup& setup) {
  std::unique_ptr<SteeringFunction> steering;
  switch (setup.steering_kind) {
    case SteeringKind::kMoveToPose: {
      MoveToPoseDef def = setup.steering;
      if (!(setup.goal_tolerance_fraction > 0.0 && setup.goal_tolerance_fraction <= 1.0)) {
        throw Error("planScenario: goal_tolerance_fraction must be in (0, 1]");
      }
      def.position_tolerance_m = setup.goal_tolerance_fraction * scenario.goal.position_tolerance_m;
      def.heading_tolerance_rad =
          setup.goal_tolerance_fraction * scenario.goal.heading_tolerance_rad;
      def.turn_in_place_radius_m =
          std::min(def.turn_in_place_radius_m, 0.8 * def.position_tolerance_m);
      steering = std::make_unique<MoveToPoseSteering>(scenario.robot, def);
      break;
    }
    case SteeringKind::kRotateTranslateRotate:
      steering = std::make_unique<RotateTranslateRotateSteering>(scenario.robot,
                                                                 setup.rotate_translate_rotate);
      break;
  }
  if (!steering) throw Error("planScenario: unknown steering kind");
  // The same rule as the world reader's, so a world the reader accepts never fails here for
  // its start or goal (the tree planner's own checks then agree up to Bullet's rounding).
  const double margin = 0.5 * setup.validation.resolution_m;
  if (const std::optional<std::string> problem = placementProblem(scenario, scenario.start, margin)) {
    PlanResult r;
    r.status = PlanStatus::kInvalidStart;
    r.message = "start: " + *problem;
    return r;
  }
  if (const std::optional<std::string> problem = goalPlacementProblem(scenario, margin)) {
    PlanResult r;
    r.status = PlanStatus::kInvalidGoal;
    r.message = "goal: " + *problem;
    return r;
  }
  const MotionValidator validator(checker, scenario.robot, scenario.lot, setup.validation);
  const TreePlanner planner(scenario.robot, scenario.lot, *steering, validator, setup.planner);
  return planner.solve(scenario.start, scenario.goal);
}

}  // namespace parksim
