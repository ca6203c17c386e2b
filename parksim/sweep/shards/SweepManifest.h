#pragma once
// DIR/sweep.json: what a sweep directory was asked to hold (the spec, the shard, every episode
// id of the whole sweep), so that `parksim merge` can list the episodes that are missing.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "parksim/sweep/shards/Shard.h"
#include "parksim/sweep/shards/SlurmScript.h"

namespace parksim {

struct SweepManifest {
  std::string spec_path;  ///< as given on the command line
  std::string name;       ///< SweepSpec::name
  Shard shard;
  std::vector<std::string> episode_ids;  ///< every id of the whole sweep, canonical order
  /// Array tasks of the Slurm script `--slurm` wrote into this directory (DIR/sweep.sbatch), so
  /// that `--slurm --missing` deals the episodes to the same shards; 0 when there is none.
  int slurm_shards = 0;
  /// What each of those tasks asked Slurm for (SlurmDef's cpus_per_task, mem, time, partition,
  /// account and max_parallel; its other fields are not recorded), so that `--slurm --missing`
  /// asks for the same unless its own command line names other values. Empty without a Slurm
  /// script, and in manifests written before it was recorded.
  std::optional<SlurmDef> slurm_request = std::nullopt;
};

/// Writes DIR/sweep.json atomically.
void writeSweepManifest(const std::string& dir, const SweepManifest& manifest);

/// Reads DIR/sweep.json; false when there is none. Throws Error when it exists but is not one.
bool readSweepManifest(const std::string& dir, SweepManifest& manifest);

/// The manifest in `text` (a sweep.json's bytes); `path` names it in messages. Throws Error
/// when it is not one.
SweepManifest parseSweepManifest(std::string_view text, const std::string& path);

}  // namespace parksim
