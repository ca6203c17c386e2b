#pragma once
// The one planner interface (OMPL's ob::Planner::solve with its problem definition): a
// planning problem in, a PlanResult out. parksim's own planners (time-a-star, hybrid-a-star,
// the tree planners) implement it exactly as a user's planner does, and are found by name in a
// PlannerRegistry (PlannerRegistry.h), built in or loaded from a plugin.
//
//   class StraightLine : public parksim::Planner {
//    public:
//     parksim::PlanResult solve(const parksim::PlanningProblem& problem) override {
//       parksim::SteerResult s = problem.steering.steer(problem.scenario.start, {},
//                                                       problem.scenario.goal.pose,
//                                                       parksim::SteerMode::kToGoal);
//       parksim::PlanResult r;
//       if (!s.reached || !problem.validator.isValid(s.trajectory)) return r;  // unsolved
//       r.status = parksim::PlanStatus::kSolved;
//       r.trajectory = std::move(s.trajectory);
//       return r;
//     }
//   };
//
// Expected outcomes are status values (PlanStatus: solved, iteration or time limit, cancelled,
// invalid start or goal); bad configuration throws Error. A plan from a planner that is not
// built in is checked before it is driven (PlanCheck.h), so a user's planner cannot fake one.

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "parksim/core/model/FootprintChecker.h"
#include "parksim/core/model/Scenario.h"
#include "parksim/core/params/ComponentRegistry.h"
#include "parksim/core/params/ParamMap.h"
#include "parksim/core/params/ParamSet.h"
#include "parksim/planner/base/PlanResult.h"
#include "parksim/planner/base/SearchDef.h"
#include "parksim/planner/motion/MotionValidator.h"
#include "parksim/planner/motion/SteeringFunction.h"
#include "parksim/planner/motion/TimeOptimalTiming.h"

namespace parksim {

struct PlanSetup;

/// Everything a planner may use, valid for the duration of one solve() call.
struct PlanningProblem {
  /// The world as planned: the robot (footprint, wheel base, radius, speed and acceleration
  /// limits), the lot's bounds, the obstacles (with names and shapes), the start and the goal
  /// region with its position and heading tolerances.
  const Scenario& scenario;
  /// State validity: Bullet's collision world answering "does the footprint at this pose
  /// overlap an obstacle" (collision/BulletCollisionWorld.h).
  const FootprintChecker& checker;
  /// Motion validity without gaps: a trajectory's swept footprint against every obstacle and
  /// the lot's bounds, at setup.validation's resolution (MotionValidator.h). What parksim's
  /// own planners validate with, and what a user's plan is checked with.
  const MotionValidator& validator;
  /// The setup's steering function (setup.steering_kind): connects two poses with a drivable
  /// trajectory. Tree planners grow their trees with it; the A* planners ignore it.
  const SteeringFunction& steering;
  /// The setup as resolved (resolvedPlanSetup): search.max_iterations is the budget (never
  /// kAutoIterations), search.seed the seed, search.max_time_s the wall-time budget,
  /// search.cancel the cancel flag; steering, smoothing and timing settings.
  const PlanSetup& setup;
  /// The robot's timing limits less the feedback headroom, with the control period plans are
  /// timed at (TimeOptimalTiming.h); a plan over them is refused when it is checked.
  TimingLimits limits;
  /// Told of the search's progress (done of budget), for displays; may be empty.
  PlanProgress progress;
  /// The run's limit on a user's planner, s (UserCodeLimits::planner_s, `--planner-timeout`;
  /// 0: none): the watch of a worker process enforces it on code in parksim's process, and a
  /// planner that runs a program of its own (the command planner) stops the program at it.
  double time_limit_s = 0.0;

  /// The search settings (setup.search).
  const SearchDef& search() const;
  /// The planner's parameters by name (setup.planner_params), already applied by its factory.
  const ParamMap& params() const;
};

class Planner {
 public:
  virtual ~Planner() = default;

  /// Plans from problem.scenario.start into problem.scenario.goal. A solved result holds the
  /// trajectory to drive: rows at increasing times from the start pose, each with the wheel
  /// speeds held until the next row (Trajectory.h), ending within the goal's tolerance.
  /// Unsolved: a status saying why, a one-line message, no trajectory. The search stops within
  /// problem.search().max_iterations and, when set, max_time_s or cancel.
  virtual PlanResult solve(const PlanningProblem& problem) = 0;
};

/// What the registry knows of a planner besides how to make one.
struct PlannerInfo {
  std::string name;         ///< registered name, as --planner and sweep specs write it
  std::string description;  ///< one line, for help texts
  /// Connects poses with the problem's steering function: `--steering` applies to it (and the
  /// results' steering column is meaningful).
  bool uses_steering = false;
  /// Keeps improving its plan until its budget ends (RRT*), rather than stopping at the first.
  bool anytime = false;
  /// The iteration budget when the setup says kAutoIterations, for a scenario. Empty: 2000
  /// iterations times max(1, the lot's size in study lots, lotSizeInStudyLots).
  std::function<int(const Scenario&)> default_budget;
  /// Its declared parameters (ParamSet.h), for help texts and docs.
  std::vector<ParamInfo> params;
  /// Set by the entry: the planner runs code parksim does not own (a command, a Python
  /// object), so it is not trusted even when registered without a plugin.
  bool runs_user_code = false;
  /// Set by the entry: that user code runs in a process of its own, with time limits of its
  /// own (a command): parksim's process needs no watch for it (UserCodeIsolation.h).
  bool own_process = false;
  /// Set by the registry: parksim's own code (no plugin, no user code), which validates every
  /// plan as it builds it. A plan from any other planner is checked before it is driven
  /// (PlanCheck.h), and what it throws is a planner_error, not an input error.
  bool trusted = false;
  /// The plugin that registered it ("" for built-ins).
  std::string plugin;
  /// Set by a front end that registers user code of its own (neither a plugin's nor a command):
  /// what it is, for results ("Python object my_module.Straight"; plan.json's planner_origin).
  std::string origin;
};

/// Makes a planner with its parameters applied; throws Error naming the planner and the
/// parameter on an unknown name or a bad value.
using PlannerFactory = std::function<std::unique_ptr<Planner>(const ParamMap& params)>;

struct PlannerEntry {
  static constexpr const char* kKind = "planner";
  PlannerInfo info;
  PlannerFactory make;
};

/// A PlannerEntry whose planner type P is constructed as P(def) from a Def struct D, whose
/// parameters `bind(def, params)` declares on a ParamSet: the Def's initializers are the
/// defaults, and the same binding both lists the parameters and applies a ParamMap.
template <class P, class D>
PlannerEntry plannerEntry(PlannerInfo info, D def, void (*bind)(D&, ParamSet&)) {
  const std::string owner = "planner " + info.name;
  info.params = declaredParams(owner, def, bind);
  return {std::move(info), boundFactory<Planner, P>(owner, std::move(def), bind)};
}

}  // namespace parksim
