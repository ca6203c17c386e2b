#pragma once
// A request's settings made concrete: the planning setup with its automatic choices, the
// execution with the realism and noise seed applied, the tolerance with the overrides applied.
// runEpisodePipeline uses them; a front-end that steps an episode itself (Python's Episode)
// takes them from here, so it drives and judges exactly as the pipeline would.

#include <vector>

#include "parksim/core/model/TrackingTolerance.h"
#include "parksim/core/system/UserCodeWatch.h"
#include "parksim/pipeline/EpisodeRequest.h"
#include "parksim/planner/base/PlanScenario.h"
#include "parksim/sim/episode/ExecutionDef.h"
#include "parksim/usercode/ComponentCheck.h"

namespace parksim {

struct EpisodeSettings {
  PlanSetup plan;               ///< resolvedPlanSetup(request.plan, scenario)
  ExecutionDef execution;       ///< realism, noise seed and executed-row stride applied
  TrackingTolerance tolerance;  ///< the world's, with request.tolerance applied
};

/// Limits of a request (docs/limits.md).
inline constexpr int kMaxRealisations = 10'000;

/// Checks everything about `request` that needs no planning or simulation: a world, a known
/// realism, realisations and success fraction in range, a given plan that is well-formed
/// (PlanCheck.h's malformedPlan), starts at the world's start and whose episode stays within the
/// step and frame limits, a planning setup within the planning limits, a registered planner and
/// controller that accept their parameters. Throws Error with one line naming the value (and the
/// plan file). runEpisodePipeline calls it first; front-ends call it before they create an output
/// directory, so bad input writes nothing. The planner and controller are made to check their
/// parameters (ComponentCheck.h): in this process, under request.watch when one is set; a
/// plugin's in a watched process with `check` {.limits = the run's, .isolate = true} (front-ends
/// that run the episode in one).
void checkEpisodeRequest(const EpisodeRequest& request, const ComponentCheckDef& check = {});

/// checkEpisodeRequest without making the planner and controller: what it would make, for
/// checkComponents (a sweep makes each distinct one once, not once per episode).
std::vector<ComponentParams> checkEpisodeValues(const EpisodeRequest& request);

/// The settings `request` runs with. Throws Error on an unknown realism.
EpisodeSettings resolveSettings(const EpisodeRequest& request);

/// The planners and controllers `request` selects from (request.components, or parksim's own).
const Components& componentsOf(const EpisodeRequest& request);

/// Whether `request` runs code parksim does not own in parksim's own process (an untrusted
/// planner when it plans, an untrusted controller when it drives closed loop; not a command,
/// which runs in a process of its own): front-ends then run it in a watched child
/// (UserCodeIsolation.h).
bool runsUserCode(const EpisodeRequest& request);

/// The executed-row stride for `rate_hz` rows per simulated second at `time_step_s` (1 for
/// rate 0: every step).
int executedStride(double rate_hz, double time_step_s);

}  // namespace parksim
