#pragma once
// A whole episode as data out: the plan, what was driven and measured, the one verdict, and
// which files were written. runEpisodePipeline (EpisodePipeline.h) returns it; front-ends print
// it (`parksim run`), tabulate it (sweeps) or hand it to Python.

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "parksim/core/model/TrackingTolerance.h"
#include "parksim/core/model/Trajectory.h"
#include "parksim/pipeline/Verdict.h"
#include "parksim/planner/base/PlanResult.h"
#include "parksim/planner/base/PlanScenario.h"
#include "parksim/renders/film/FrameRecorder.h"
#include "parksim/scenario/world/World.h"
#include "parksim/sim/episode/Episode.h"
#include "parksim/sim/episode/ExecutionDef.h"

namespace parksim {

/// One drive of the plan under one noise seed.
struct RealisationOutcome {
  std::uint64_t noise_seed = 0;
  EpisodeMetrics metrics;
  Verdict verdict;
};

struct EpisodeOutcome {
  /// The world the episode ran in (the request's).
  std::shared_ptr<const World> world;
  /// The planning setup as used: defaults and automatic choices made (resolvedPlanSetup).
  PlanSetup plan_setup;
  /// The planner's result; unset when the request gave a plan to drive.
  std::optional<PlanResult> plan;
  /// The plan driven (the planner's trajectory or the given one); empty when planning failed.
  /// A plan that failed its check (plan_invalid) is here too, never driven.
  Trajectory trajectory;
  /// plan.json's content (planSummary), or a given plan's own statistics (trajectorySummary).
  nlohmann::json plan_summary;

  /// How the plan was driven (the first realisation's noise seed), and the tolerance judged.
  ExecutionDef execution;
  TrackingTolerance tolerance;
  /// The first realisation in full: rows at the recorded rate, metrics, pose samples.
  EpisodeResult episode;
  /// Every realisation, the first included; empty when nothing was driven.
  std::vector<RealisationOutcome> realisations;
  /// The verdict on the whole request (judgeRealisations over the realisations; plan_failed
  /// when planning failed; met for a solved plan-only request).
  Verdict verdict;

  /// metrics.json's content: for a request that drives, whatever its verdict (without
  /// measurements when nothing was driven); empty for a plan-only request.
  nlohmann::json metrics;
  /// The film, when one was made.
  std::optional<RecordingResult> recording;
  /// Files written, as paths under the request's out_dir ("trajectory.csv", "figures/plan.png").
  std::vector<std::string> files;

  /// True when the plan was driven.
  bool driven() const { return !realisations.empty(); }
  /// Realisations that met their tolerance.
  int realisationsMet() const;
};

}  // namespace parksim
