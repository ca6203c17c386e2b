#pragma once
// A sweep from its spec to its table: the spec read and expanded with the planners and
// controllers it may name (parksim's own, its plugins', and those a front-end adds: Python
// objects), then one shard of it run into DIR, resuming what DIR's table already holds. What
// `parksim sweep` and Python's parksim.sweep() both run.

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "parksim/results/tables/ResultsTable.h"
#include "parksim/sweep/run/SweepRunner.h"
#include "parksim/sweep/shards/Shard.h"
#include "parksim/sweep/spec/EpisodeExpansion.h"
#include "parksim/sweep/spec/SweepSpec.h"
#include "parksim/usercode/Components.h"

namespace parksim {

/// A spec read, its worlds loaded and its episodes expanded, in canonical order.
struct SweepPlan {
  SweepSpec spec;
  std::vector<SweepWorld> worlds;
  std::shared_ptr<const Components> components;
  std::vector<SweepEpisode> episodes;
};

/// Reads and checks everything (nothing is written). `extra`: planners and controllers a
/// front-end adds to the spec's plugins' (it must outlive the plan's episodes); their names
/// must not clash. `check`: where a plugin's planners and controllers are made to check their
/// parameters (the run's user code limits; expandEpisodes). Throws Error naming the spec's file
/// and line.
SweepPlan prepareSweep(const std::string& spec_path, const Components* extra = nullptr,
                       const ComponentCheckDef& check = {});

/// The expectations a resumed table must meet: the worlds' contents now, this build and the
/// same plugins (`provenance`, SweepRunnerDef's), the spec's set: columns.
TableExpectations sweepExpectations(const SweepPlan& plan,
                                    const nlohmann::ordered_json& provenance);

/// What runSweepJob tells before it runs anything.
struct SweepStart {
  std::vector<std::string> repairs;  ///< what opening the table repaired (ResultsTable.h)
  std::size_t episodes = 0;          ///< of the shard
  std::size_t already = 0;           ///< of those, in the table already
};

struct SweepJobResult {
  SweepProgress progress;
  std::vector<SweepEpisode> episodes;  ///< the shard's, canonical order
  std::size_t failed = 0;              ///< of those (earlier runs' included), not met
};

/// Runs `shard` of `plan` into `out`: opens (creates, repairs, checks) its table, writes
/// sweep.json, runs the episodes not in the table yet (def: workers, limits, fork hooks; its
/// episode files go to out/episodes), and counts the verdicts. `def.provenance` gains the
/// `plugins` column. Throws Error before anything is written when the table is another
/// sweep's, build's or plugins'.
SweepJobResult runSweepJob(const SweepPlan& plan, const Shard& shard, const std::string& out,
                           SweepRunnerDef def, const std::function<void(const SweepStart&)>& start,
                           const SweepProgressFn& progress);

}  // namespace parksim
