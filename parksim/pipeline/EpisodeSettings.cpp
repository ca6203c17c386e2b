#include "parksim/pipeline/EpisodeSettings.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <optional>
#include <string>

#include "parksim/core/geometry/Angle.h"
#include "parksim/core/io/Error.h"
#include "parksim/core/io/NumberFormat.h"
#include "parksim/core/io/Text.h"
#include "parksim/planner/base/PlanCheck.h"
#include "parksim/realism/DriveSizing.h"
#include "parksim/realism/RealismDef.h"
#include "parksim/sim/episode/Episode.h"

namespace parksim {

namespace {

std::string poseText(const Pose2& p) {
  return "(" + formatFixed(p.x, 4) + ", " + formatFixed(p.y, 4) + ", " +
         formatFixed(radToDeg(p.theta), 2) + " deg)";
}

void checkRealismName(const std::string& name) {
  const std::vector<std::string> choices = realismChoices();
  if (std::find(choices.begin(), choices.end(), name) != choices.end()) return;
  throw Error("realism: unknown value '" + name + "' (expected one of " + joinNames(choices) + ")");
}

// A given plan must start where the world starts (within 1 mm and 0.5 deg, the planner's own
// goal tolerance); anything else is a plan for another world.
void checkGivenPlan(const EpisodeRequest& request, const Scenario& scenario) {
  const std::string& source =
      request.given_plan_source.empty() ? std::string("plan") : request.given_plan_source;
  if (request.given_plan->points.empty()) throw Error(source + ": the plan has no points");
  if (const std::optional<std::string> problem = malformedPlan(*request.given_plan)) {
    throw Error(source + ": " + *problem);
  }
  const Pose2& first = request.given_plan->points.front().pose;
  if (positionDistance(first, scenario.start) > 0.001 ||
      headingDistance(first, scenario.start) > degToRad(0.5)) {
    throw Error(source + ": the plan starts at " + poseText(first) + ", not at the world's start " +
                poseText(scenario.start));
  }
}

}  // namespace

int executedStride(double rate_hz, double time_step_s) {
  if (rate_hz <= 0.0) return 1;
  return std::max(1, static_cast<int>(std::lround(1.0 / (rate_hz * time_step_s))));
}

EpisodeSettings resolveSettings(const EpisodeRequest& request) {
  if (!request.world) throw Error("episode request: no world");
  checkRealismName(request.realism);
  const World& world = *request.world;
  EpisodeSettings s;
  s.plan = resolvedPlanSetup(request.plan, world.scenario, componentsOf(request).planners);
  s.execution = request.execution;
  if (request.realism != "world") {
    // The preset's motors sized to the world's robot (a car's, realism/DriveSizing.h).
    s.execution.realism =
        presetRealismFor(request.realism, world.scenario.robot, world.scenario.physics);
  } else {
    s.execution.realism = world.sections.has_realism ? world.sections.realism : RealismDef{};
  }
  s.execution.noise_seed = request.noise_seed;
  if (request.record.executed_rate_hz > 0.0) {
    s.execution.csv_stride_steps =
        executedStride(request.record.executed_rate_hz, world.scenario.physics.time_step_s);
  }
  s.tolerance = request.tolerance.appliedTo(world.sections.tolerance);
  return s;
}

void checkEpisodeRequest(const EpisodeRequest& request, const ComponentCheckDef& check) {
  const std::vector<ComponentParams> made = checkEpisodeValues(request);
  ComponentCheckDef def = check;
  if (def.watch == nullptr) def.watch = request.watch;
  checkComponents(componentsOf(request), made, def);
}

std::vector<ComponentParams> checkEpisodeValues(const EpisodeRequest& request) {
  std::vector<ComponentParams> made;
  const EpisodeSettings settings = resolveSettings(request);
  const Scenario& scenario = request.world->scenario;
  if (request.realisations < 1 || request.realisations > kMaxRealisations) {
    throw Error("realisations: must be in [1, " + std::to_string(kMaxRealisations) + "], got " +
                std::to_string(request.realisations));
  }
  if (!(request.min_success_fraction >= 0.0 && request.min_success_fraction <= 1.0)) {
    throw Error("min_success_fraction: must be in [0, 1], got " +
                formatGeneral(request.min_success_fraction));
  }
  if (!(request.record.executed_rate_hz >= 0.0 && request.record.executed_rate_hz <= 1e6)) {
    throw Error("executed_rate_hz: must be in [0, 1e+06], got " +
                formatGeneral(request.record.executed_rate_hz));
  }
  if (request.film.when != FilmWhen::kNever) checkFilmMemory(request.film.frames);
  if (request.given_plan) {
    checkGivenPlan(request, scenario);
    if (request.drive) {
      // Physics steps and frames are bounded by the plan's duration: checked before any work.
      checkEpisodeLimits(scenario, *request.given_plan, settings.execution);
      if (request.film.when != FilmWhen::kNever) {
        checkFrameLimits(request.film.frames,
                         request.given_plan->duration() + settings.execution.max_stop_time_s);
      }
    }
  } else {
    checkPlanningLimits(scenario, settings.plan, componentsOf(request).planners);
    made.push_back(
        {ComponentParams::Kind::kPlanner, settings.plan.planner, settings.plan.planner_params});
  }
  if (request.drive && settings.execution.tracking == TrackingMode::kClosed) {
    made.push_back(
        {ComponentParams::Kind::kController, request.controller, request.controller_params});
  }
  return made;
}

bool runsUserCode(const EpisodeRequest& request) {
  const Components& c = componentsOf(request);
  const PlannerInfo& planner = c.planners.find(request.plan.planner).info;
  if (!request.given_plan && !planner.trusted && !planner.own_process) return true;
  const ControllerInfo& controller = c.controllers.find(request.controller).info;
  return request.drive && request.execution.tracking == TrackingMode::kClosed &&
         !controller.trusted && !controller.own_process;
}

const Components& componentsOf(const EpisodeRequest& request) {
  return request.components ? *request.components : *builtInComponents();
}

}  // namespace parksim
