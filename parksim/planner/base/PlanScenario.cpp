#include "parksim/planner/base/PlanScenario.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <optional>
#include <random>
#include <string>

#include "parksim/core/io/Error.h"
#include "parksim/core/io/NumberFormat.h"
#include "parksim/planner/base/FreeSpaceBound.h"
#include "parksim/planner/base/GripCheck.h"
#include "parksim/planner/base/PlanCheck.h"
#include "parksim/planner/motion/SpeedProfile.h"

namespace parksim {

const char* toString(SteeringKind kind) {
  switch (kind) {
    case SteeringKind::kMoveToPose: return "move-to-pose";
    case SteeringKind::kRotateTranslateRotate: return "rotate-translate-rotate";
    case SteeringKind::kReedsShepp: return "reeds-shepp";
    case SteeringKind::kBalkcomMason: return "balkcom-mason";
  }
  return "?";
}

std::vector<SteeringKind> allSteeringKinds() {
  return {SteeringKind::kMoveToPose, SteeringKind::kRotateTranslateRotate,
          SteeringKind::kReedsShepp, SteeringKind::kBalkcomMason};
}

SteeringKind steeringKindFromString(const std::string& name) {
  std::string known;
  for (SteeringKind k : allSteeringKinds()) {
    if (name == toString(k)) return k;
    known += (known.empty() ? "" : ", ") + std::string(toString(k));
  }
  throw Error("unknown steering '" + name + "' (expected one of " + known + ")");
}

void checkPlanningLimits(const Scenario& scenario, const PlanSetup& setup,
                         const PlannerRegistry& registry) {
  const RobotDef& robot = scenario.robot;
  auto refuse = [](const std::string& what, double periods) {
    throw Error(what + " needs " + formatGeneral(periods, 3) +
                " control periods, more than the limit of " + formatGeneral(kMaxProfilePeriods, 6) +
                " per trajectory (docs/limits.md)");
  };
  double speed_fraction = 1.0;
  double accel_fraction = 1.0;
  double period_s = 0.1;
  const char* name = "";
  switch (setup.steering_kind) {
    case SteeringKind::kMoveToPose: {
      const MoveToPoseDef& d = setup.steering;
      const double periods = d.max_duration_s / d.period_s;
      if (!(periods <= kMaxProfilePeriods)) {
        refuse("move-to-pose steering (max_duration_s)", periods);
      }
      return;
    }
    case SteeringKind::kRotateTranslateRotate:
      speed_fraction = setup.rotate_translate_rotate.speed_fraction;
      accel_fraction = setup.rotate_translate_rotate.accel_fraction;
      period_s = setup.rotate_translate_rotate.period_s;
      name = "rotate-translate-rotate steering";
      break;
    case SteeringKind::kReedsShepp:
      speed_fraction = setup.reeds_shepp.speed_fraction;
      period_s = setup.reeds_shepp.period_s;
      name = "reeds-shepp steering";
      break;
    case SteeringKind::kBalkcomMason:
      speed_fraction = setup.balkcom_mason.speed_fraction;
      period_s = setup.balkcom_mason.period_s;
      name = "balkcom-mason steering";
      break;
  }
  // All build rest-to-rest speed profiles at the wheel limits: braking from full speed, then
  // moves as long as the lot (the diagonal; Reeds-Shepp and Balkcom-Mason paths are a few times
  // longer at most) and, for rotate-translate-rotate, half turns in place.
  const double wheel_max = speed_fraction * robot.max_wheel_speed_radps;
  const double wheel_step = accel_fraction * robot.max_wheel_accel_radps2 * period_s;
  if (!(wheel_max > 0.0) || !(wheel_step > 0.0) || !(period_s > 0.0)) {
    throw Error(std::string(name) + ": wheel speed, acceleration and period must be positive");
  }
  const double r = robot.wheel_radius_m;
  const double half_base = 0.5 * robot.wheel_base_m;
  const double diagonal = std::hypot(scenario.lot.x_max_m - scenario.lot.x_min_m,
                                     scenario.lot.y_max_m - scenario.lot.y_min_m);
  const double brake = wheel_max / wheel_step;
  if (!(brake <= kMaxProfilePeriods)) {
    refuse(std::string(name) + ": braking from " + formatGeneral(wheel_max) + " rad/s at " +
               formatGeneral(wheel_step / period_s) + " rad/s^2",
           brake);
  }
  if (setup.steering_kind == SteeringKind::kRotateTranslateRotate) {
    const double turn =
        restToRestPeriods(kPi, wheel_max * r / half_base, wheel_step * r / half_base, period_s);
    if (!(turn <= kMaxProfilePeriods)) {
      refuse(std::string(name) + ": a half turn (wheel radius " + formatGeneral(r) +
                 " m, wheel base " + formatGeneral(robot.wheel_base_m) + " m)",
             turn);
    }
  }
  // The tree planners steer between samples anywhere in the lot; the A* planners' moves and
  // expansions follow the problem (their search window grows from the start and the goal), so
  // for them the move that bounds a trajectory is the one from the start to the goal.
  const bool across_lot = registry.find(setup.planner).info.uses_steering;
  const double length =
      across_lot ? diagonal : positionDistance(scenario.start, scenario.goal.pose);
  const double cross = restToRestPeriods(length, wheel_max * r, wheel_step * r, period_s);
  if (!(cross <= kMaxProfilePeriods)) {
    refuse(std::string(name) + ": a straight move " +
               (across_lot ? "across the lot (" : "from the start to the goal (") +
               formatGeneral(length) + " m, wheel radius " + formatGeneral(r) + " m)",
           cross);
  }
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

const SearchDef& PlanningProblem::search() const { return setup.search; }

const ParamMap& PlanningProblem::params() const { return setup.planner_params; }

PlanSetup resolvedPlanSetup(const PlanSetup& setup, const Scenario& scenario,
                            const PlannerRegistry& registry) {
  PlanSetup resolved = setup;
  resolved.validation = resolvedValidation(setup.validation, scenario.robot);
  resolved.planner = plannerFor(setup.planner, scenario.robot);
  if (scenario.robot.isCar()) {
    // A car cannot turn in place: the steering functions that turn in place give way to
    // Reeds-Shepp curves.
    if (setup.steering_kind != SteeringKind::kReedsShepp) {
      resolved.steering_kind = SteeringKind::kReedsShepp;
    }
  }
  if (resolved.search.max_iterations == kAutoIterations) {
    resolved.search.max_iterations =
        defaultIterationBudget(registry.find(resolved.planner).info, scenario);
  }
  return resolved;
}

namespace {

std::unique_ptr<SteeringFunction> makeSteering(const Scenario& scenario, const PlanSetup& setup) {
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
      return std::make_unique<MoveToPoseSteering>(scenario.robot, def);
    }
    case SteeringKind::kRotateTranslateRotate:
      return std::make_unique<RotateTranslateRotateSteering>(scenario.robot,
                                                             setup.rotate_translate_rotate);
    case SteeringKind::kReedsShepp:
      return std::make_unique<ReedsSheppSteering>(scenario.robot, setup.reeds_shepp);
    case SteeringKind::kBalkcomMason:
      return std::make_unique<BalkcomMasonSteering>(scenario.robot, setup.balkcom_mason);
  }
  throw Error("planScenario: unknown steering kind");
}

// A failed result when the start or the goal is not a valid placement.
std::optional<PlanResult> placementFailure(const Scenario& scenario, const PlanSetup& setup) {
  // The same rule as the world reader's, so a world the reader accepts never fails here for
  // its start or goal (the planners' own checks then agree up to Bullet's rounding).
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
  return std::nullopt;
}

// A user's planner, whose failures are its own (UserCodeError), not the input's: anything it
// throws, a status only parksim gives, and a solved result without a trajectory that can even
// be checked. A solved plan that can is checked (PlanCheck.h): one that fails is kPlanInvalid.
PlanResult solveUserPlanner(Planner& planner, const PlannerInfo& info,
                            const PlanningProblem& problem) {
  const auto failed = [&](const std::string& what) {
    return UserCodeError(UserCodeError::Component::kPlanner, "planner " + info.name + " " + what);
  };
  PlanResult result;
  try {
    result = planner.solve(problem);
  } catch (const UserCodeError&) {
    throw;
  } catch (const std::exception& e) {
    throw failed(std::string("threw: ") + e.what());
  } catch (...) {
    throw failed("threw something that is not a std::exception");
  }
  if (result.status == PlanStatus::kPlanInvalid) {
    throw failed("returned the status plan_invalid, which only parksim's plan check gives");
  }
  if (result.solved()) {
    if (std::optional<std::string> problem_text = malformedPlan(result.trajectory)) {
      throw failed("returned an unusable plan: " + *problem_text);
    }
  } else {
    // Unsolved plans carry no trajectory to drive.
    result.trajectory = {};
  }
  return result;
}

// The plan's bounds: its own geometry's (durationLowerBound) and the free-space optimum's.
void setBounds(const Scenario& scenario, const TimingLimits& limits, PlanResult& result) {
  result.duration_lower_bound_s = durationLowerBound(pathPieces(result.trajectory), limits);
  result.free_space_bound_s = scenarioFreeSpaceBound(scenario, limits);
}

}  // namespace

PlanResult planScenario(const Scenario& scenario, const FootprintChecker& checker,
                        const PlanSetup& requested, const PlanProgress& progress,
                        const PlannerRegistry& registry, double time_limit_s) {
  const PlanSetup setup = resolvedPlanSetup(requested, scenario, registry);
  const PlannerEntry& entry = registry.find(setup.planner);
  checkPlanningLimits(scenario, setup, registry);
  const std::unique_ptr<SteeringFunction> steering = makeSteering(scenario, setup);
  if (!(setup.feedback_headroom >= 0.0 && setup.feedback_headroom < 1.0)) {
    throw Error("planScenario: feedback_headroom must be in [0, 1)");
  }
  if (!(setup.timing_period_s > 0.0)) throw Error("planScenario: timing_period_s must be > 0");
  // Its parameters are checked before anything else is done (a bad one is the input's fault).
  const std::unique_ptr<Planner> planner = entry.make(setup.planner_params);
  if (std::optional<PlanResult> failed = placementFailure(scenario, setup)) return *failed;
  const MotionValidator validator(checker, scenario.robot, scenario.lot, setup.validation);
  const TimingLimits limits = timingLimits(scenario.robot, setup.feedback_headroom,
                                           setup.timing_period_s, setup.start_jerk_radps3);
  const PlanningProblem problem{scenario, checker, validator, *steering,
                                setup,    limits,  progress,  time_limit_s};
  PlanResult result;
  if (entry.info.trusted) {
    result = planner->solve(problem);
  } else {
    // A user's planner is timed here, whatever it reports: the same clock for every planner.
    const auto t0 = std::chrono::steady_clock::now();
    result = solveUserPlanner(*planner, entry.info, problem);
    PlanStats& st = result.stats;
    st.times.total_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (result.solved() && st.first_solution_s < 0.0) {
      st.first_solution_s = st.times.total_s;
      st.first_solution_iteration = st.iterations;
    }
  }
  // The one check of a plan parksim did not make, whichever front end asked for it; a car's
  // plans are checked whoever made them (its steering limits, docs/cars.md). parksim's own
  // planners validate a differential drive's plans as they build them (MotionValidator.h).
  if (result.solved() && (!entry.info.trusted || scenario.robot.isCar())) {
    if (const std::optional<PlanViolation> v =
            checkPlan(scenario, checker, result.trajectory, setup.validation)) {
      result.status = PlanStatus::kPlanInvalid;
      result.message = v->reason;
    }
  } else if (result.solved()) {
    // parksim's own plans keep the robot's limits, but the grip those limits ask may be more
    // than the tyres have (GripCheck.h): such a plan is refused, not driven into a slip.
    if (const std::optional<PlanViolation> v = gripViolation(scenario, result.trajectory)) {
      result.status = PlanStatus::kPlanInvalid;
      result.message = v->reason;
    }
  }
  if (result.solved()) setBounds(scenario, limits, result);
  return result;
}

}  // namespace parksim
