#pragma once
// Plans a scenario end to end: the planner selected by name (Planner.h, PlannerRegistry.h) on
// a problem made of the world, the gap-free motion validation against the given footprint
// checker, the selected steering function and the timing limits; then the plan's bounds.

#include <string>
#include <vector>

#include "parksim/core/model/FootprintChecker.h"
#include "parksim/core/model/Scenario.h"
#include "parksim/core/params/ParamMap.h"
#include "parksim/planner/base/PathSmoother.h"
#include "parksim/planner/base/PlannerRegistry.h"
#include "parksim/planner/base/SearchDef.h"
#include "parksim/planner/motion/MotionValidator.h"
#include "parksim/planner/steering/BalkcomMasonSteering.h"
#include "parksim/planner/steering/MoveToPoseSteering.h"
#include "parksim/planner/steering/ReedsSheppSteering.h"
#include "parksim/planner/steering/RotateTranslateRotateSteering.h"

namespace parksim {

enum class SteeringKind {
  kMoveToPose,             ///< the study's polar controller ("move-to-pose")
  kRotateTranslateRotate,  ///< turn, drive straight, turn; exact ("rotate-translate-rotate")
  kReedsShepp,             ///< forward and reverse arcs and straights; exact ("reeds-shepp")
  /// The robot's fastest free-space paths: turns in place and straight drives; exact
  /// ("balkcom-mason", BalkcomMason.h).
  kBalkcomMason,
};

const char* toString(SteeringKind kind);
/// Every steering kind, in a fixed order (for benchmarks and help texts).
std::vector<SteeringKind> allSteeringKinds();
/// Parses "move-to-pose", "rotate-translate-rotate", "reeds-shepp" or "balkcom-mason"; throws
/// Error otherwise.
SteeringKind steeringKindFromString(const std::string& name);

/// How the returned plan is timed along its geometry.
enum class TimingKind {
  /// Re-timed to the fastest profile within the speed limit less the feedback headroom and the
  /// acceleration limit, stopping at every cusp (TimeOptimalTiming.h): "time-optimal".
  kTimeOptimal,
  /// As the steering function drove it (the study's controller for move-to-pose): "study".
  kStudy,
};

const char* toString(TimingKind kind);
/// Parses "time-optimal" or "study"; throws Error otherwise.
TimingKind timingKindFromString(const std::string& name);

/// parksim's planning defaults, the same for every front-end (the command line, sweeps, Python,
/// the episode pipeline): time-a-star (Hybrid A* in time, TimeAStar.h) with smoothing and the
/// automatic budget, balkcom-mason steering for the tree planners, time-optimal timing with 20%
/// feedback headroom and rows every 0.02 s. What only one planner reads is that planner's
/// parameter (planner_params), with its default in its own Def.
struct PlanSetup {
  /// The planner by its registered name (PlannerRegistry.h): a built-in one or a plugin's.
  std::string planner = "time-a-star";
  /// Parameters of the selected planner by name (ParamMap.h), applied by its factory; an
  /// unknown name is an error.
  ParamMap planner_params;
  /// Seed, budget (kAutoIterations: the planner's budget for the lot), wall time, cancel flag,
  /// cost weights and smoothing: PlanFinishing.h smooths every built-in plan (time-a-star smooths
  /// each path it finds itself).
  SearchDef search;
  SteeringKind steering_kind = SteeringKind::kBalkcomMason;
  /// Move-to-pose parameters; its to-goal tolerance is taken from the scenario's goal region,
  /// scaled by goal_tolerance_fraction.
  MoveToPoseDef steering;
  /// The move-to-pose controller stops as soon as it is within tolerance, so aiming at the
  /// goal's own tolerance leaves plans ending on its edge (0.496 deg of 0.5) and a tracked
  /// execution with no margin. Plans aim at this fraction of the goal's tolerances instead.
  double goal_tolerance_fraction = 0.5;
  /// Rotate-translate-rotate parameters.
  RotateTranslateRotateDef rotate_translate_rotate;
  /// Reeds-Shepp parameters (also the curves of Hybrid A*'s analytic expansion).
  ReedsSheppDef reeds_shepp;
  /// Balkcom-Mason steering parameters.
  BalkcomMasonDef balkcom_mason;
  /// Smoothing (search.smooth) with time-optimal timing, for every planner; with study timing
  /// the tree planners use their own shortcut smoothing (ShortcutSmoother.h).
  PathSmootherDef smoothing;
  MotionValidatorDef validation;
  TimingKind timing = TimingKind::kTimeOptimal;
  /// Share of the wheel-speed limit left to feedback: time-optimal plans drive the wheels at
  /// most (1 - feedback_headroom) times the limit, so a tracking controller can add corrections
  /// without saturating. In [0, 1).
  double feedback_headroom = 0.2;
  /// Rows of a time-optimal plan are this far apart, s (> 0). Each row may change a wheel's
  /// speed by one acceleration step (limit x period): 0.02 s keeps the steps at 0.8 rad/s,
  /// which the motors' speed loops follow (docs/planning.md).
  double timing_period_s = 0.02;
  /// Jerk limit of the first speed-up from rest of a time-optimal plan, rad/s^3 (>= 0, 0:
  /// none): from standstill the drive train's static friction and the speed loop's lag let the
  /// robot fall behind a plan that starts at full acceleration (TimeOptimalTiming.h).
  double start_jerk_radps3 = 100.0;
};

/// `setup` with its automatic choices made for `scenario`: a budget of kAutoIterations becomes
/// the planner's default budget for the lot (PlannerRegistry.h); the planner is plannerFor's
/// (car-a-star for time-a-star when the robot is a car, and the other way round). For a car
/// (RobotDef::isCar), which cannot turn in place, the steering is Reeds-Shepp, whose arcs are at
/// least the car's tightest radius (ReedsSheppSteering.h). planScenario plans with this, and result
/// files record it. Throws Error when `registry` has no such planner.
PlanSetup resolvedPlanSetup(const PlanSetup& setup, const Scenario& scenario,
                            const PlannerRegistry& registry = builtInPlanners());

/// Refuses, before any work, a setup whose steering would build unbounded trajectories in this
/// scenario: rotate-translate-rotate profiles (a straight move across the lot's diagonal, a
/// half turn, braking from full speed) or a move-to-pose trajectory longer than
/// kMaxProfilePeriods control periods. Throws Error with one line naming the values and the
/// limit (docs/limits.md). planScenario calls it first.
void checkPlanningLimits(const Scenario& scenario, const PlanSetup& setup,
                         const PlannerRegistry& registry = builtInPlanners());

/// Plans with the selected planner (found in `registry` by setup.planner, its parameters
/// applied) and steering: resolves the setup, checks its limits, refuses an invalid start or
/// goal as a status, hands the planner its problem (Planner.h) and sets a solved plan's duration
/// lower bound and free-space bound. parksim's planners smooth and time their plans themselves
/// (PlanFinishing.h). A planner that is not built in and throws, or returns a solved result
/// without a usable trajectory (empty, non-finite, times not increasing), raises
/// UserCodeError (core/Error.h); its solved plan (and any car's) is checked here (checkPlan, PlanCheck.h), and
/// one that fails is returned as PlanStatus::kPlanInvalid with the violation as its message and
/// the plan kept. Every front end plans through here, so none can drive, draw or report such a
/// plan as solved. `progress` and `time_limit_s` (the run's limit on a user's planner, s; 0:
/// none) are handed to the planner in its problem (Planner.h).
PlanResult planScenario(const Scenario& scenario, const FootprintChecker& checker,
                        const PlanSetup& setup, const PlanProgress& progress = {},
                        const PlannerRegistry& registry = builtInPlanners(),
                        double time_limit_s = 0.0);

}  // namespace parksim
