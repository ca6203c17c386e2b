#pragma once
// The Slurm job-array script `parksim sweep SPEC --slurm --out DIR` writes to DIR/sweep.sbatch:
// array task I runs `parksim sweep SPEC --shard I/N --out DIR/shards/I`, which resumes, so the
// same script can be submitted again after a failure and only the missing episodes run
// (`sbatch --array=3,7 DIR/sweep.sbatch` resubmits just those shards). Tasks exit 0 when their
// episodes ran, even if some missed their tolerance: that is a result, not a job failure.

#include <string>

namespace parksim {

struct SlurmDef {
  std::string job_name = "parksim-sweep";
  int shards = 1;                 ///< array tasks, one shard each
  int cpus_per_task = 1;          ///< also the sweep's --workers
  std::string mem = "1G";         ///< --mem per task
  std::string time = "01:00:00";  ///< --time per task
  std::string partition;          ///< --partition; empty: the cluster's default
  std::string account;            ///< --account; empty: none
  std::string max_parallel;       ///< array throttle ("%K"), empty: none
  std::string parksim_exe;        ///< absolute path of the parksim program
  std::string spec_path;          ///< absolute path of the spec
  std::string out_dir;            ///< absolute path of DIR
};

/// The script's text. Throws Error on a non-positive shard or CPU count.
std::string sbatchScript(const SlurmDef& def);

/// Throws Error "NAME: ..." unless `value` can stand on an #SBATCH line: one word of letters,
/// digits and _.:,+=@/%- (sbatchScript checks every field so, named by its option).
void checkSbatchWord(const std::string& value, const std::string& name);
/// The same for an array throttle, which must also be empty or %K with K from 1 to 100000.
void checkArrayThrottle(const std::string& value, const std::string& name);

}  // namespace parksim
