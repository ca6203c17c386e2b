#pragma once
// One sweep episode end to end: set up (EpisodeSetup.h), plan, simulate, measure, judge against
// the tolerance, and write the episode's own files. Builds its own Bullet collision and dynamics
// worlds, so workers run episodes side by side with nothing shared but read-only inputs.

#include <mutex>
#include <string>

#include <nlohmann/json.hpp>

#include "parksim/sweep/EpisodeExpansion.h"
#include "parksim/sweep/SweepSpec.h"

namespace parksim {

struct EpisodeRunDef {
  RecordDef record;
  /// Episode files go to episodes_dir/<episode_id>/ (executed.csv, trajectory.csv, frames/).
  std::string episodes_dir;
  /// Serialises filming (one off-screen GL context at a time); required when
  /// record.film_failures is set.
  std::mutex* film_mutex = nullptr;
};

/// Outcome classes, the row's `status`.
inline constexpr const char* kStatusMet = "met";
inline constexpr const char* kStatusPlanFailed = "plan_failed";
inline constexpr const char* kStatusContact = "contact";
inline constexpr const char* kStatusGoalMissed = "goal_missed";
inline constexpr const char* kStatusToleranceMissed = "tolerance_missed";

/// The episode's results row, without provenance (see ResultsTable.h for its keys): id,
/// parameters, status, met_tolerance, failure (one line; empty when met), plan statistics,
/// simulation metrics (absent when the plan failed) and timing. The tolerance is the episode's
/// (EpisodeSetup::tolerance). Throws Error when a file cannot
/// be written.
nlohmann::ordered_json runSweepEpisode(const SweepEpisode& episode, const EpisodeRunDef& def);

}  // namespace parksim
