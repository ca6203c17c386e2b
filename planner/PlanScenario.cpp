#include "planner/PlanScenario.h"

namespace parksim {

PlanResult planScenario(const Scenario& scenario, const FootprintChecker& checker,
                        const PlanSetup& setup) {
  MoveToPoseDef steering_def = setup.steering;
  steering_def.position_tolerance_m = scenario.goal.position_tolerance_m;
  steering_def.heading_tolerance_rad = scenario.goal.heading_tolerance_rad;
  steering_def.turn_in_place_radius_m =
      std::min(steering_def.turn_in_place_radius_m, 0.8 * steering_def.position_tolerance_m);
  const MoveToPoseSteering steering(scenario.robot, steering_def);
  const MotionValidator validator(checker, scenario.robot, scenario.lot, setup.validation);
  const TreePlanner planner(scenario.robot, scenario.lot, steering, validator, setup.planner);
  return planner.solve(scenario.start, scenario.goal);
}

}  // namespace parksim
