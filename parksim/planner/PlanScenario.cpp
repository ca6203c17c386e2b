#include "parksim/planner/PlanScenario.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <optional>
#include <string>

#include "parksim/core/Error.h"

namespace parksim {

const char* toString(SteeringKind kind) {
  switch (kind) {
    case SteeringKind::kMoveToPose: return "move-to-pose";
    case SteeringKind::kRotateTranslateRotate: return "rotate-translate-rotate";
    case SteeringKind::kReedsShepp: return "reeds-shepp";
  }
  return "?";
}

std::vector<SteeringKind> allSteeringKinds() {
  return {SteeringKind::kMoveToPose, SteeringKind::kRotateTranslateRotate,
          SteeringKind::kReedsShepp};
}

SteeringKind steeringKindFromString(const std::string& name) {
  std::string known;
  for (SteeringKind k : allSteeringKinds()) {
    if (name == toString(k)) return k;
    known += (known.empty() ? "" : ", ") + std::string(toString(k));
  }
  throw Error("unknown steering '" + name + "' (expected one of " + known + ")");
}

const char* toString(TimingKind kind) {
  switch (kind) {
    case TimingKind::kTimeOptimal: return "time-optimal";
    case TimingKind::kStudy: return "study";
  }
  return "?";
}

TimingKind timingKindFromString(const std::string& name) {
  for (TimingKind k : {TimingKind::kTimeOptimal, TimingKind::kStudy}) {
    if (name == toString(k)) return k;
  }
  throw Error("unknown timing '" + name + "' (expected one of time-optimal, study)");
}

int defaultIterationBudget(PlannerKind kind, const LotBounds& lot) {
  const double base = kind == PlannerKind::kHybridAStar ? 20000.0 : 2000.0;
  const double area = (lot.x_max_m - lot.x_min_m) * (lot.y_max_m - lot.y_min_m);
  return static_cast<int>(std::ceil(base * std::max(1.0, area / kStudyLotAreaM2)));
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
    case SteeringKind::kReedsShepp:
      steering = std::make_unique<ReedsSheppSteering>(scenario.robot, setup.reeds_shepp);
      break;
  }
  if (!(setup.feedback_headroom >= 0.0 && setup.feedback_headroom < 1.0)) {
    throw Error("planScenario: feedback_headroom must be in [0, 1)");
  }
  if (!steering) throw Error("planScenario: unknown steering kind");
  // The same rule as the world reader's, so a world the reader accepts never fails here for
  // its start or goal (the tree planner's own checks then agree up to Bullet's rounding).
  const double margin = 0.5 * setup.validation.resolution_m;
  if (const std::optional<std::string> problem =
          placementProblem(scenario, scenario.start, margin)) {
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
  const TimingLimits limits = timingLimits(scenario.robot, setup.feedback_headroom);
  PlanResult result;
  if (setup.planner.kind == PlannerKind::kHybridAStar) {
    const ReedsSheppSteering curves(scenario.robot, setup.reeds_shepp);
    const HybridAStar planner(scenario.robot, scenario.lot, curves, validator, setup.planner,
                              setup.hybrid_a_star);
    result = planner.solve(scenario.start, scenario.goal);
  } else {
    const TreePlanner planner(scenario.robot, scenario.lot, *steering, validator, setup.planner);
    result = planner.solve(scenario.start, scenario.goal);
  }
  if (!result.solved()) return result;
  const auto t0 = std::chrono::steady_clock::now();
  const std::vector<PathPiece> pieces = pathPieces(result.trajectory);
  if (setup.timing == TimingKind::kTimeOptimal) {
    const long before = validator.queries();
    Trajectory timed =
        timePieces(result.trajectory.points.front().pose, pieces, scenario.robot, limits);
    if (validator.isValid(timed)) {
      result.trajectory = std::move(timed);
      const CostWeights w{setup.planner.reverse_penalty, setup.planner.cusp_penalty_m};
      result.cost = trajectoryCost(result.trajectory, scenario.robot, w);
    }
    result.stats.collision_queries += validator.queries() - before;
  }
  result.duration_lower_bound_s = durationLowerBound(pieces, limits);
  result.stats.times.timing_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  result.stats.times.total_s += result.stats.times.timing_s;
  return result;
}

}  // namespace parksim
