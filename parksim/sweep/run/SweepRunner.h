#pragma once
// Runs a sweep's episodes on N workers and appends each finished episode to the results table
// at once, from one writer (the calling thread), in order of completion. Each row's content
// depends only on its episode (timing keys aside), never on the worker count, the order in
// which episodes finish, or whether the workers are threads or processes.
//
// Workers are threads while every planner and controller of the episodes is parksim's own.
// When one is user code (a plugin's, a Python object's, a command's: pipeline/EpisodeSettings.h
// runsUserCode), they are processes (usercode/UserCodeIsolation.h, one per worker, reused from
// episode to episode): an episode whose user code crashes or hangs past its limit then becomes
// a row with its planner_error or controller_error, the worker is replaced, and the sweep goes
// on.

#include <cstddef>
#include <functional>
#include <vector>

#include "parksim/results/tables/ResultsTable.h"
#include "parksim/sweep/run/EpisodeRun.h"
#include "parksim/sweep/spec/EpisodeExpansion.h"
#include "parksim/usercode/UserCodeIsolation.h"

namespace parksim {

struct SweepProgress {
  std::size_t done = 0;    ///< episodes in the table (earlier runs included)
  std::size_t total = 0;   ///< episodes of this run's share of the sweep
  std::size_t failed = 0;  ///< of done, those that did not meet their tolerance
  std::size_t ran = 0;     ///< finished by this run
  double elapsed_s = 0.0;  ///< wall time of this run so far
};

using SweepProgressFn = std::function<void(const SweepProgress&)>;

/// The provenance columns of every row: this binary's (core/system/Provenance.h: parksim_version,
/// git_commit, git_dirty, build_type, compiler, bullet_precision) and this machine's `host`.
nlohmann::ordered_json provenanceColumns();

/// At most this many workers (threads or processes) per sweep.
inline constexpr int kMaxSweepWorkers = 1024;

/// One per CPU (at least 1, at most kMaxSweepWorkers): `--workers`' and parksim.sweep()'s
/// default.
int defaultSweepWorkers();

struct SweepRunnerDef {
  int workers = 1;  ///< threads or processes, in [1, kMaxSweepWorkers]
  EpisodeRunDef episode;
  nlohmann::ordered_json provenance = provenanceColumns();  ///< added to every row
  /// Limits on user code (core/UserCodeWatch.h): in worker processes, and on every episode's
  /// command planner and controller (EpisodeRunDef::limits, set from here).
  UserCodeLimits limits;
  /// Run around each fork of a worker process (an embedding interpreter's).
  ForkHooks fork_hooks;
  /// Processes even when no episode runs user code.
  bool processes = false;
};

/// Throws Error when `def`'s workers or limits are out of range.
void checkSweepRunnerDef(const SweepRunnerDef& def);

/// Whether `episodes` run user code, so that runSweep runs them in worker processes.
bool sweepRunsUserCode(const std::vector<SweepEpisode>& episodes);

/// Runs the episodes of `episodes` not yet in `table` and appends their rows (with provenance).
/// Calls `progress` (if set) from the calling thread once at the start and after every row.
/// A worker's exception (a file that cannot be written) stops the others after their current
/// episode and is rethrown; rows written until then stay. Returns the final progress.
/// Processes are forked from the calling thread.
SweepProgress runSweep(const std::vector<SweepEpisode>& episodes, const SweepRunnerDef& def,
                       ResultsTable& table, const SweepProgressFn& progress = {});

}  // namespace parksim
