#pragma once
// Plans a scenario end to end: the selected planner and steering function, gap-free motion
// validation against the given footprint checker, smoothing, timing and the plan's bounds.

#include <string>
#include <vector>

#include "parksim/core/FootprintChecker.h"
#include "parksim/core/ParamMap.h"
#include "parksim/core/Scenario.h"
#include "parksim/planner/BalkcomMasonSteering.h"
#include "parksim/planner/HybridAStar.h"
#include "parksim/planner/MotionValidator.h"
#include "parksim/planner/MoveToPoseSteering.h"
#include "parksim/planner/PathSmoother.h"
#include "parksim/planner/ReedsSheppSteering.h"
#include "parksim/planner/RotateTranslateRotateSteering.h"
#include "parksim/planner/TimeAStar.h"
#include "parksim/planner/TreePlanner.h"

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

/// planner.max_iterations: the budget chosen for the lot (defaultIterationBudget), resolved
/// when the plan is made (resolvedPlanSetup).
inline constexpr int kAutoIterations = 0;

/// parksim's planning defaults, the same for every front-end (the command line, sweeps, Python,
/// the episode pipeline): time-a-star (Hybrid A* in time, TimeAStar.h) with smoothing and the
/// automatic budget, balkcom-mason steering for the tree planners, time-optimal timing with 20%
/// feedback headroom and rows every 0.02 s.
struct PlanSetup {
  /// max_iterations kAutoIterations (the default): defaultIterationBudget(kind, lot). smooth:
  /// PathSmoother.h after every planner (time-a-star smooths each path it finds itself).
  PlannerDef planner{.kind = PlannerKind::kTimeAStar,
                     .max_iterations = kAutoIterations,
                     .smooth = true,
                     .smoothing_attempts = 300};
  /// Parameters of the selected planner by name (ParamMap.h), for the planner to read.
  ParamMap planner_params;
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
  /// Hybrid A* parameters (planner.kind == kHybridAStar; it ignores steering_kind).
  HybridAStarDef hybrid_a_star;
  /// Hybrid A* in time (planner.kind == kTimeAStar; it ignores steering_kind).
  TimeAStarDef time_a_star;
  /// Smoothing (planner.smooth) with time-optimal timing, for every planner; with study timing
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

/// Area of the study's lot (1.8 x 1.2 m), the unit of the default budget's scaling, m^2.
inline constexpr double kStudyLotAreaM2 = 1.8 * 1.2;

/// The default iteration budget of `kind` on `lot`: the base budget (tree planners: the study's
/// 2000 iterations; hybrid-a-star: 20000 node expansions) times max(1, lot area / study lot
/// area), rounded up, so budgets grow with the space to search. time-a-star searches a window
/// around the start and the goal whatever the lot (SearchWindow.h): 200000 expansions per
/// search, for any lot.
int defaultIterationBudget(PlannerKind kind, const LotBounds& lot);

/// `setup` with its automatic choices made for `scenario`: an iteration budget of
/// kAutoIterations becomes defaultIterationBudget(kind, lot). planScenario plans with this, and
/// result files record it.
PlanSetup resolvedPlanSetup(const PlanSetup& setup, const Scenario& scenario);

/// Refuses, before any work, a setup whose steering would build unbounded trajectories in this
/// scenario: rotate-translate-rotate profiles (a straight move across the lot's diagonal, a
/// half turn, braking from full speed) or a move-to-pose trajectory longer than
/// kMaxProfilePeriods control periods. Throws Error with one line naming the values and the
/// limit (docs/limits.md). planScenario calls it first.
void checkPlanningLimits(const Scenario& scenario, const PlanSetup& setup);

/// Plans with the selected planner and steering, smooths the plan (planner.smooth), then times
/// it as `timing` says (the re-timed trajectory is validated again; if rounding ever made it
/// fail, the planner's own timing is kept) and sets its duration lower bound and the free-space
/// bound. `progress` is passed to the planner.
PlanResult planScenario(const Scenario& scenario, const FootprintChecker& checker,
                        const PlanSetup& setup, const PlanProgress& progress = {});

}  // namespace parksim
