#pragma once
// `parksim sweep SPEC --out DIR --slurm --missing`: after array tasks died (a node failure,
// scancel, a time limit), finds the shards of DIR whose tables lack some of their episodes and
// submits DIR/sweep.sbatch again for those array tasks alone (`sbatch --array=LIST`). Each task
// resumes its shard's table, so only the missing episodes run.

#include <cstddef>
#include <string>
#include <vector>

#include "parksim/sweep/spec/EpisodeExpansion.h"

namespace parksim {

/// One array task's shard, as its table in DIR/shards/I stands.
struct ShardState {
  int index = 0;
  std::size_t episodes = 0;  ///< the shard's share of the sweep
  std::size_t done = 0;      ///< of those, rows in DIR/shards/I/results.jsonl (checked)
  bool running = false;      ///< a sweep holds that table now: its task still runs
  bool complete() const { return done == episodes; }
};

/// The state of every shard of the Slurm sweep in DIR: `episodes` (canonical order) dealt to
/// `shards` shards as the script does (Shard.h). Throws Error naming the file and line of a
/// shard table's changed row.
std::vector<ShardState> slurmShardStates(const std::string& dir,
                                         const std::vector<SweepEpisode>& episodes, int shards);

/// "3,7,12": the array indices of the shards to run again (neither complete nor running).
std::string arrayList(const std::vector<ShardState>& states);

struct Submission {
  std::string job_id;  ///< as sbatch --parsable prints it
  int exit_code = 0;   ///< sbatch's (with `wait`, the job's: non-zero when a task failed)
};

/// Runs `sbatch --parsable --array=LIST [--wait] SCRIPT` with its output in `log_path`; LIST
/// ends in the array's throttle ("%4") when it has one.
/// Throws EnvironmentError when sbatch is not installed, Error when it did not submit (its
/// output quoted).
Submission submitArrayTasks(const std::string& script, const std::string& array_list, bool wait,
                            const std::string& log_path);

}  // namespace parksim
