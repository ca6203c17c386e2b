#include "parksim/sweep/EpisodeSetup.h"

#include <algorithm>

#include "parksim/core/Angle.h"
#include "parksim/core/Error.h"

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

const std::vector<std::string>& supportedRealismPresets() {
  static const std::vector<std::string> presets = {"ideal"};
  return presets;
}

const std::vector<std::string>& supportedTimings() {
  static const std::vector<std::string> timings = {"study"};
  return timings;
}

EpisodeSetup setupEpisode(const EpisodeParams& p, const Scenario& world) {
  requireOneOf("realism", p.realism, supportedRealismPresets());
  requireOneOf("timing", p.timing, supportedTimings());
  if (p.realism == "ideal" && p.noise_seed != 0) {
    throw Error("noise_seed: the ideal preset has no noise; use 0");
  }
  EpisodeSetup s;
  s.scenario = world;
  s.scenario.start = applyOffset(world.start, p.start_offset);
  s.scenario.goal.pose = applyOffset(world.goal.pose, p.goal_offset);
  if (!s.scenario.lot.contains(s.scenario.start.x, s.scenario.start.y)) {
    throw Error("start offset moves the start of " + world.name + " outside the lot");
  }
  if (!s.scenario.lot.contains(s.scenario.goal.pose.x, s.scenario.goal.pose.y)) {
    throw Error("goal offset moves the goal of " + world.name + " outside the lot");
  }

  s.plan.planner.kind = plannerKindFromString(p.planner);
  s.plan.planner.seed = p.seed;
  s.plan.planner.max_iterations = p.max_iterations;
  s.plan.planner.smooth = p.smooth;
  s.plan.planner.record_tree = false;  // the tree is for figures; a sweep keeps statistics only
  s.plan.steering_kind = steeringKindFromString(p.steering);

  s.execution.tracking = trackingModeFromString(p.tracking);
  return s;
}

}  // namespace parksim
