#pragma once
// One sweep episode end to end: its parameters as a request (EpisodeSetup.h), one call of the
// episode pipeline (plan, simulate, measure, judge, write the episode's own files, film a
// failure), and the outcome as a results row. The pipeline builds its own Bullet collision and
// dynamics worlds, so workers run episodes side by side with nothing shared but read-only
// inputs.

#include <mutex>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "parksim/core/system/UserCodeWatch.h"
#include "parksim/pipeline/EpisodeOutcome.h"
#include "parksim/pipeline/Verdict.h"
#include "parksim/results/tables/EpisodeRecord.h"
#include "parksim/sweep/spec/EpisodeExpansion.h"
#include "parksim/sweep/spec/SweepSpec.h"

namespace parksim {

struct EpisodeRunDef {
  SweepRecordDef record;
  /// Episode files go to episodes_dir/<episode_id>/ (executed.csv, trajectory.csv, frames/).
  std::string episodes_dir;
  /// Serialises filming (one off-screen GL context at a time); required when
  /// record.film_failures is set.
  std::mutex* film_mutex = nullptr;
  /// The limits on user code (EpisodeRequest::limits): a command planner or controller stops
  /// its program at them; in worker processes the watch enforces them too (SweepRunner.h).
  UserCodeLimits limits;
};

/// The episode's results row, without provenance: its id, its parameters (EpisodeParams.h)
/// and the episode record read from its outcome (results/EpisodeRecord.h: the verdict, the
/// plan's statistics, the measurements when it was driven, timing, world_hash). Throws Error
/// when a file cannot be written.
/// `watch`, when given, is told when the episode's user code runs (a sweep's worker process,
/// SweepRunner.h).
nlohmann::ordered_json runSweepEpisode(const SweepEpisode& episode, const EpisodeRunDef& def,
                                       UserCodeWatch* watch = nullptr);

/// The episode's request, without the sweep's recording choices.
EpisodeRequest sweepEpisodeRequest(const SweepEpisode& episode);

/// The row of an episode whose user code crashed or hung its process (`verdict`: the
/// planner_error or controller_error of pipeline/Verdict.h's userCodeVerdict): nothing measured.
nlohmann::ordered_json failedEpisodeRow(const SweepEpisode& episode, const Verdict& verdict);

/// A row: `id` (none when empty), the parameters and the record read from `facts`.
nlohmann::ordered_json episodeRow(const std::string& id, const EpisodeParams& params,
                                  const EpisodeFacts& facts);

/// One request's realisations as records without ids (one record for a plan that was not
/// driven): its parameters (episodeParamsOf) with each realisation's noise seed, and that
/// realisation's measurements and verdict. `parksim run --junit` reports them.
std::vector<nlohmann::ordered_json> realisationRecords(const EpisodeRequest& request,
                                                       const EpisodeOutcome& outcome);

}  // namespace parksim
