#include "parksim/sweep/EpisodeSetup.h"

#include <algorithm>
#include <optional>

#include "parksim/core/Angle.h"
#include "parksim/core/Error.h"
#include "parksim/realism/RealismDef.h"

namespace parksim {
namespace {

Pose2 applyOffset(const Pose2& pose, const PoseOffset& o) {
  return {pose.x + o.dx_m, pose.y + o.dy_m, wrapAngle(pose.theta + degToRad(o.dyaw_deg))};
}

void requireOneOf(const std::string& what, const std::string& value,
                  const std::vector<std::string>& allowed) {
  if (std::find(allowed.begin(), allowed.end(), value) != allowed.end()) return;
  std::string list;
  for (const std::string& a : allowed) list += (list.empty() ? "" : ", ") + a;
  throw Error(what + ": unknown value '" + value + "' (this build has: " + list + ")");
}

}  // namespace

std::vector<std::string> supportedRealismPresets() {
  std::vector<std::string> names = {"world"};
  for (const std::string& n : realismPresetNames()) names.push_back(n);
  return names;
}

std::vector<std::string> supportedTimings() {
  return {toString(TimingKind::kTimeOptimal), toString(TimingKind::kStudy)};
}

EpisodeSetup setupEpisode(const EpisodeParams& p, const SweepWorld& world,
                          const ToleranceOverrides& tolerance) {
  requireOneOf("realism", p.realism, supportedRealismPresets());
  requireOneOf("timing", p.timing, supportedTimings());
  EpisodeSetup s;
  s.scenario = world.scenario;
  s.scenario.start = applyOffset(world.scenario.start, p.start_offset);
  s.scenario.goal.pose = applyOffset(world.scenario.goal.pose, p.goal_offset);
  // The world reader's one placement rule, so a perturbed episode is one it would accept.
  if (!p.start_offset.isZero()) {
    if (const std::optional<std::string> why = placementProblem(s.scenario, s.scenario.start)) {
      throw Error("start offset on " + world.scenario.name + ": " + *why);
    }
  }
  if (!p.goal_offset.isZero()) {
    if (const std::optional<std::string> why = goalPlacementProblem(s.scenario)) {
      throw Error("goal offset on " + world.scenario.name + ": " + *why);
    }
  }

  s.plan.planner.kind = plannerKindFromString(p.planner);
  s.plan.planner.seed = p.seed;
  s.plan.planner.max_iterations = p.max_iterations;
  s.plan.planner.smooth = p.smooth;
  s.plan.planner.record_tree = false;  // the tree is for figures; a sweep keeps statistics only
  s.plan.steering_kind = steeringKindFromString(p.steering);
  s.plan.timing = timingKindFromString(p.timing);

  s.execution.tracking = trackingModeFromString(p.tracking);
  // As `parksim run`: a preset replaces the world's realism: section; "world" keeps it.
  if (p.realism != "world") {
    s.execution.realism = presetRealism(p.realism);
  } else if (world.realism.has_realism) {
    s.execution.realism = world.realism.realism;
  }
  s.execution.noise_seed = p.noise_seed;
  s.tolerance = tolerance.appliedTo(world.realism.tolerance);
  return s;
}

}  // namespace parksim
