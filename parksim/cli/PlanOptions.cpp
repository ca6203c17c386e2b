#include "parksim/cli/PlanOptions.h"

#include <cstdint>

#include "parksim/cli/ComponentOptions.h"
#include "parksim/cli/Validators.h"
#include "parksim/core/io/Error.h"
#include "parksim/core/io/NumberFormat.h"
#include "parksim/core/io/Text.h"
#include "parksim/core/params/ParamSet.h"
#include "parksim/usercode/CommandLine.h"
#include "parksim/usercode/CommandPlanner.h"

namespace parksim::cli {

namespace {

template <class Kind>
std::string namesOf(const std::vector<Kind>& kinds) {
  std::string names;
  for (Kind k : kinds) names += (names.empty() ? "" : ", ") + std::string(toString(k));
  return names;
}

}  // namespace

void PlanCliOptions::addTo(CLI::App& sub, const PlannerRegistry& planners) {
  CLI::Option* by_name =
      sub.add_option("--planner", planner,
                     "planner by name: " + joinNames(planners.names()) +
                         " (or a plugin's: --plugin); `parksim list` lists them with their "
                         "parameters")
          ->capture_default_str();
  sub.add_option("--planner-param", planner_params,
                 "NAME=VALUE: a parameter of the selected planner (repeatable)");
  sub.add_option("--planner-command", planner_command,
                 "'CMD ... {problem} {out}': plan with a program in any language, run without a "
                 "shell; it reads the problem file {problem} and writes {out}/trajectory.csv "
                 "(the planner `command`, docs/your-code.md)")
      ->excludes(by_name);
  sub.add_option("--steering", steering,
                 "steering function, one of: " + namesOf(allSteeringKinds()))
      ->capture_default_str();
  // CLI11 would wrap "-3" and clamp 2^64 into a 64-bit unsigned seed; refuse both instead.
  sub.add_option("--seed", seed, "seed of the planner's random number generator")
      ->capture_default_str()
      ->check(unsigned64());
  sub.add_option(
         "--max-iterations", max_iterations,
         "iteration budget (A* planners: node expansions); auto: 200000 per search for "
         "time-a-star (car-a-star: at least 20000), else 2000 (tree planners; 20000 for a car) or "
         "20000 (hybrid-a-star) times max(1, lot area / 2.16 m^2 / (robot size / 85 "
         "mm)^2)")
      ->capture_default_str();
  sub.add_option("--time-limit", time_limit_s,
                 "wall-time budget of the search, s (0: none); the plan then depends on the "
                 "machine's speed, so reproducible runs use --max-iterations alone")
      ->capture_default_str()
      ->check(realIn(0.0, 3600.0));
  sub.add_flag("--smooth,!--no-smooth", smooth,
               "shortcut-smooth the plan (study 3(c)(3)); --no-smooth: do not")
      ->capture_default_str();
  sub.add_option("--smoothing-attempts", smoothing_attempts, "random shortcuts tried by --smooth")
      ->capture_default_str()
      ->check(integerIn(0, kMaxSmoothingAttempts));
  sub.add_option("--timing", timing,
                 "time-optimal: re-time the plan to the fastest wheel speeds within the limits "
                 "(less the feedback headroom); study: keep the steering controller's timing")
      ->capture_default_str()
      ->check(CLI::IsMember({"time-optimal", "study"}));
  sub.add_option("--feedback-headroom", feedback_headroom,
                 "share of the wheel-speed limit time-optimal plans leave to feedback, in [0, 1)")
      ->capture_default_str()
      ->check(realIn(0.0, 0.99));
  sub.add_option("--turning-radius", turning_radius_m,
                 "arc radius of reeds-shepp steering and of hybrid-a-star's primitives, m")
      ->capture_default_str()
      ->check(realIn(0.0, 100.0, true));
}

int parseIterationBudget(const std::string& text, const std::string& option) {
  if (text == "auto") return kAutoIterations;
  long long value = -1;
  if (!parseInt(text, value) || value < 1 || value > kMaxPlannerIterations) {
    throw Error(option + ": expected auto or an integer in [1, " +
                std::to_string(kMaxPlannerIterations) + "], got '" + text + "'");
  }
  return static_cast<int>(value);
}

PlanSetup PlanCliOptions::toSetup() const {
  PlanSetup setup;
  setup.planner = planner;
  setup.planner_params = paramMapFrom(planner_params, "--planner-param");
  if (!planner_command.empty()) {
    setup.planner = kCommandPlanner;
    if (setup.planner_params.count(kCommandParam) != 0) {
      throw Error("--planner-command and --planner-param command=... both give the command");
    }
    setup.planner_params[kCommandParam] =
        quoteCommandLine(splitCommandLine(planner_command, "--planner-command"));
  }
  setup.search.seed = seed;
  setup.search.max_iterations = parseIterationBudget(max_iterations);
  setup.search.max_time_s = time_limit_s;
  setup.timing = timingKindFromString(timing);
  setup.feedback_headroom = feedback_headroom;
  setup.reeds_shepp.turning_radius_m = turning_radius_m;
  setup.search.smooth = smooth;
  setup.search.smoothing_attempts = smoothing_attempts;
  setup.steering_kind = steeringKindFromString(steering);
  return setup;
}

}  // namespace parksim::cli
