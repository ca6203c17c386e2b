#pragma once
// One sweep episode end to end: its parameters as a request (EpisodeSetup.h), one call of the
// episode pipeline (plan, simulate, measure, judge, write the episode's own files, film a
// failure), and the outcome as a results row. The pipeline builds its own Bullet collision and
// dynamics worlds, so workers run episodes side by side with nothing shared but read-only
// inputs.

#include <mutex>
#include <string>

#include <nlohmann/json.hpp>

#include "parksim/sweep/EpisodeExpansion.h"
#include "parksim/sweep/SweepSpec.h"

namespace parksim {

struct EpisodeRunDef {
  SweepRecordDef record;
  /// Episode files go to episodes_dir/<episode_id>/ (executed.csv, trajectory.csv, frames/).
  std::string episodes_dir;
  /// Serialises filming (one off-screen GL context at a time); required when
  /// record.film_failures is set.
  std::mutex* film_mutex = nullptr;
};

/// The episode's results row, without provenance (see ResultsTable.h for its keys): id,
/// parameters, status (the verdict's, pipeline/Verdict.h), met_tolerance, failure (the
/// verdict's one line; empty when met), plan statistics, simulation metrics (absent when the
/// plan failed), timing and world_hash (the world's content_hash). Throws Error when a file
/// cannot be written.
nlohmann::ordered_json runSweepEpisode(const SweepEpisode& episode, const EpisodeRunDef& def);

}  // namespace parksim
