#include "parksim/planner/PlanScenario.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>

#include "parksim/core/Error.h"
#include "parksim/planner/SpeedProfile.h"

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

void checkPlanningLimits(const Scenario& scenario, const PlanSetup& setup) {
  const RobotDef& robot = scenario.robot;
  auto refuse = [](const std::string& what, double periods) {
    char text[400];
    std::snprintf(text, sizeof text,
                  "%s needs %.3g control periods, more than the limit of %.0f per trajectory "
                  "(docs/limits.md)",
                  what.c_str(), periods, kMaxProfilePeriods);
    throw Error(text);
  };
  if (setup.steering_kind == SteeringKind::kMoveToPose) {
    const MoveToPoseDef& d = setup.steering;
    const double periods = d.max_duration_s / d.period_s;
    if (!(periods <= kMaxProfilePeriods)) refuse("move-to-pose steering (max_duration_s)", periods);
    return;
  }
  const RotateTranslateRotateDef& d = setup.rotate_translate_rotate;
  const double wheel_max = d.speed_fraction * robot.max_wheel_speed_radps;
  const double wheel_step = d.accel_fraction * robot.max_wheel_accel_radps2 * d.period_s;
  if (!(wheel_max > 0.0) || !(wheel_step > 0.0) || !(d.period_s > 0.0)) {
    throw Error(
        "rotate-translate-rotate steering: wheel speed, acceleration and period must be "
        "positive");
  }
  const double r = robot.wheel_radius_m;
  const double half_base = 0.5 * robot.wheel_base_m;
  const double diagonal = std::hypot(scenario.lot.x_max_m - scenario.lot.x_min_m,
                                     scenario.lot.y_max_m - scenario.lot.y_min_m);
  char what[300];
  const double brake = wheel_max / wheel_step;
  std::snprintf(what, sizeof what,
                "rotate-translate-rotate steering: braking from %g rad/s at %g rad/s^2", wheel_max,
                wheel_step / d.period_s);
  if (!(brake <= kMaxProfilePeriods)) refuse(what, brake);
  const double turn =
      restToRestPeriods(kPi, wheel_max * r / half_base, wheel_step * r / half_base, d.period_s);
  std::snprintf(
      what, sizeof what,
      "rotate-translate-rotate steering: a half turn (wheel radius %g m, wheel base %g m)", r,
      robot.wheel_base_m);
  if (!(turn <= kMaxProfilePeriods)) refuse(what, turn);
  const double cross = restToRestPeriods(diagonal, wheel_max * r, wheel_step * r, d.period_s);
  std::snprintf(what, sizeof what,
                "rotate-translate-rotate steering: a straight move across the lot (%g m, wheel "
                "radius %g m)",
                diagonal, r);
  if (!(cross <= kMaxProfilePeriods)) refuse(what, cross);
}

PlanResult planScenario(const Scenario& scenario, const FootprintChecker& checker,
                        const PlanSetup& setup) {
  checkPlanningLimits(scenario, setup);
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
  const MotionValidator validator(checker, scenario.robot, scenario.lot, setup.validation);
  const TreePlanner planner(scenario.robot, scenario.lot, *steering, validator, setup.planner);
  return planner.solve(scenario.start, scenario.goal);
}

}  // namespace parksim
