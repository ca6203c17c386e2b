#pragma once
// An episode's page, report.html beside its metrics.json: the verdict and its line on top; the
// lot, the plan, the driven path and the robot replayed from the record with a time scrubber
// and play/pause; plots over the same time axis (position and heading error against the
// tolerance, commanded and measured wheel speeds, and under a realism the estimate's error
// against the truth); contacts where and when they happened. Drawn from the data in the page
// (canvas), not from frames: it works for episodes filmed or not (web/episode.js,
// web/replay.js; docs/pages.md).
//
// The page is a function of the episode alone: no wall-clock time goes into it, so the same
// episode gives the same bytes.

#include <cstddef>
#include <span>
#include <string>

#include <nlohmann/json.hpp>

#include "parksim/core/model/Scenario.h"
#include "parksim/core/model/TrackingTolerance.h"
#include "parksim/core/model/Trajectory.h"
#include "parksim/sim/episode/EpisodeMetrics.h"
#include "parksim/sim/episode/ExecutedRow.h"

namespace parksim {

/// Rows of the record a page holds at most (~17 min of simulated time at 240 Hz, ~60 MB of
/// page); a longer record is kept every n-th row (and its last), which the page says.
inline constexpr std::size_t kMaxEpisodePageRows = 250000;

/// An episode as its page shows it. Pointers and spans are views that must outlive the call.
struct EpisodePage {
  /// The verdict: its status name (pipeline/Verdict.h's toString: "met", "contact", ...) and
  /// its line (empty when met).
  std::string status;
  std::string reason;
  /// The plan driven; null or empty when planning failed.
  const Trajectory* plan = nullptr;
  /// The record: executed.csv's rows (the first realisation's); empty when nothing was driven.
  /// A plan that was not driven is replayed from its own poses.
  std::span<const ExecutedRow> rows;
  /// The rows carry a realism's columns (executedColumns): the page plots the estimate.
  bool realism_columns = false;
  /// The first realisation's measurements and the tolerance judged; null when not driven.
  const EpisodeMetrics* metrics = nullptr;
  const TrackingTolerance* tolerance = nullptr;
  /// Realisations driven and how many met their tolerance (the verdict is over all of them).
  int realisations = 0;
  int realisations_met = 0;
  /// plan.json's content (planSummary); its keys that do not measure wall-clock time are shown.
  const nlohmann::json* plan_summary = nullptr;
};

/// The page's data: lotData(scenario) plus "verdict", "plan" (t, x, y, theta columns and the
/// dense path), "record" (executed.csv's columns by name, exact; "stride" > 1 when cut to
/// kMaxEpisodePageRows), "contacts", "metrics"
/// (metricsToJson without wall-clock keys), "tolerance", "plan_summary" and "realisations".
nlohmann::json episodePageData(const Scenario& scenario, const EpisodePage& page);

/// Writes the page to `path` (report.html) atomically. Throws Error.
void writeEpisodePage(const std::string& path, const Scenario& scenario, const EpisodePage& page);

}  // namespace parksim
