#include "parksim/sweep/spec/EpisodeSetup.h"

#include <algorithm>
#include <optional>

#include "parksim/core/geometry/Angle.h"
#include "parksim/core/io/Error.h"
#include "parksim/core/io/Text.h"
#include "parksim/planner/base/PlanScenario.h"
#include "parksim/realism/RealismDef.h"
#include "parksim/sweep/spec/SetValues.h"

namespace parksim {
namespace {

Pose2 applyOffset(const Pose2& pose, const PoseOffset& o) {
  return {pose.x + o.dx_m, pose.y + o.dy_m, wrapAngle(pose.theta + degToRad(o.dyaw_deg))};
}

void requireOneOf(const std::string& what, const std::string& value,
                  const std::vector<std::string>& allowed) {
  if (std::find(allowed.begin(), allowed.end(), value) != allowed.end()) return;
  throw Error(what + ": unknown value '" + value + "' (this build has: " + joinNames(allowed) +
              ")");
}

}  // namespace

std::vector<std::string> supportedTimings() {
  return {toString(TimingKind::kTimeOptimal), toString(TimingKind::kStudy)};
}

namespace {

std::vector<ScenarioOverride> setOverrides(const EpisodeParams& p) {
  std::vector<ScenarioOverride> overrides;
  for (const auto& [path, value] : p.world_set) {
    overrides.push_back({path, setValueYaml(value), "set: " + path + "=" + value});
  }
  return overrides;
}

}  // namespace

std::shared_ptr<const World> episodeWorld(const EpisodeParams& p, const SweepWorld& file) {
  if (p.world_set.empty()) return {file, &file->world};
  const std::vector<ScenarioOverride> overrides = setOverrides(p);
  const std::lock_guard<std::mutex> lock(file->mutex);
  return std::make_shared<const World>(file->file.read(overrides));
}

std::shared_ptr<const World> episodeWorld(const EpisodeParams& p, const SweepWorld& file,
                                          const WorldFile& own) {
  if (p.world_set.empty()) return {file, &file->world};
  return std::make_shared<const World>(own.read(setOverrides(p)));
}

EpisodeRequest episodeRequest(const EpisodeParams& p, const std::shared_ptr<const World>& world,
                              const ToleranceOverrides& tolerance,
                              const std::shared_ptr<const Components>& components) {
  requireOneOf("realism", p.realism, realismChoices());
  requireOneOf("timing", p.timing, supportedTimings());
  EpisodeRequest r;
  r.world = world;
  r.components = components;
  if (!p.start_offset.isZero() || !p.goal_offset.isZero()) {
    auto moved = std::make_shared<World>(*world);
    Scenario& s = moved->scenario;
    s.start = applyOffset(world->scenario.start, p.start_offset);
    s.goal.pose = applyOffset(world->scenario.goal.pose, p.goal_offset);
    // The world reader's one placement rule, so a perturbed episode is one it would accept.
    if (!p.start_offset.isZero()) {
      if (const std::optional<std::string> why = placementProblem(s, s.start)) {
        throw Error("start offset on " + s.name + ": " + *why);
      }
    }
    if (!p.goal_offset.isZero()) {
      if (const std::optional<std::string> why = goalPlacementProblem(s)) {
        throw Error("goal offset on " + s.name + ": " + *why);
      }
    }
    r.world = std::move(moved);
  }
  r.plan.planner = p.planner;
  r.plan.search.seed = p.seed;
  r.plan.search.max_iterations = p.max_iterations;
  r.plan.search.smooth = p.smooth;
  r.plan.search.record_tree = false;  // the tree is for figures; a sweep keeps statistics only
  // The planner's and the controller's own parameters; they validate them (ParamMap.h).
  r.plan.planner_params = p.planner_params;
  r.controller = p.controller;
  r.controller_params = p.controller_params;
  r.plan.steering_kind = steeringKindFromString(p.steering);
  r.plan.timing = timingKindFromString(p.timing);
  r.execution.tracking = trackingModeFromString(p.tracking);
  r.realism = p.realism;
  r.noise_seed = p.noise_seed;
  r.tolerance = tolerance;
  return r;
}

EpisodeParams episodeParamsOf(const EpisodeRequest& r) {
  EpisodeParams p;
  p.world = r.world->scenario.name;
  p.world_file = r.world->scenario.source_path;
  p.planner = r.plan.planner;
  p.steering = toString(r.plan.steering_kind);
  p.smooth = r.plan.search.smooth;
  p.seed = r.plan.search.seed;
  p.max_iterations = r.plan.search.max_iterations;
  p.tracking = toString(r.execution.tracking);
  p.timing = toString(r.plan.timing);
  p.realism = r.realism;
  p.noise_seed = r.noise_seed;
  p.planner_params = r.plan.planner_params;
  p.controller = r.controller;
  p.controller_params = r.controller_params;
  return p;
}

}  // namespace parksim
