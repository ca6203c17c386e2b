#include "parksim/sweep/shards/SlurmScript.h"

#include <string_view>

#include "parksim/core/io/Error.h"
#include "parksim/core/io/NumberFormat.h"
#include "parksim/core/io/Text.h"

namespace parksim {
namespace {

// Text on a comment or #SBATCH line (paths): any character but a line break or control byte.
const std::string& onOneLine(const std::string& value, const char* what) {
  for (const char c : value) {
    if (static_cast<unsigned char>(c) < 0x20 || c == '\x7f') {
      throw Error(std::string(what) +
                  ": holds a control character, which a line of the sbatch script cannot");
    }
  }
  return value;
}

// The job name comes from the spec's name, which may hold anything: keep what Slurm shows well.
std::string jobName(const std::string& name) {
  std::string out;
  for (const char c : name) {
    const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                    c == '_' || c == '.' || c == '-';
    out += ok ? c : '_';
  }
  return out;
}

}  // namespace

// A value on an `#SBATCH` line: one word. A newline in --slurm-partition wrote a shell command
// of its own into the script, which the job then ran.
void checkSbatchWord(const std::string& value, const std::string& name) {
  for (const char c : value) {
    const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                    std::string_view("_.:,+=@/%-").find(c) != std::string_view::npos;
    if (!ok) {
      throw Error(name +
                  ": must be one word of letters, digits and _.:,+=@/%- for an #SBATCH line");
    }
  }
}

// Appended to the array's index range ("0-9%4"): anything but "%K" would change the range (a
// max_parallel of "0-5" in an edited sweep.json asked for "--array=0-90-5"). K as the command
// line's --slurm-max-parallel allows it.
void checkArrayThrottle(const std::string& value, const std::string& name) {
  checkSbatchWord(value, name);
  long long k = 0;
  if (!value.empty() && (value[0] != '%' || !parseInt(std::string_view(value).substr(1), k) ||
                         k < 1 || k > 100000 || value.find('+') != std::string::npos)) {
    throw Error(name + ": the array's throttle must be %K with K from 1 to 100000, got " + value);
  }
}

std::string sbatchScript(const SlurmDef& d) {
  if (d.shards < 1) throw Error("--slurm-shards must be at least 1");
  if (d.cpus_per_task < 1) throw Error("--slurm-cpus must be at least 1");
  checkSbatchWord(d.mem, "--slurm-mem");
  checkSbatchWord(d.time, "--slurm-time");
  checkSbatchWord(d.partition, "--slurm-partition");
  checkSbatchWord(d.account, "--slurm-account");
  checkArrayThrottle(d.max_parallel, "--slurm-max-parallel");
  onOneLine(d.out_dir, "--out");
  onOneLine(d.parksim_exe, "the parksim executable's path");
  const std::string n = std::to_string(d.shards);
  std::string s = "#!/bin/bash\n";
  s += "# Written by `parksim sweep --slurm`. Submit: sbatch --wait " + d.out_dir +
       "/sweep.sbatch\n";
  s += "# then merge: " + d.parksim_exe + " merge " + d.out_dir + "\n";
  s += "# Resubmitting is safe: every shard resumes and runs only its missing episodes;\n";
  s += "# `sbatch --array=3,7 sweep.sbatch` reruns shards 3 and 7 alone.\n";
  s += "#SBATCH --job-name=" + jobName(d.job_name) + "\n";
  s += "#SBATCH --array=0-" + std::to_string(d.shards - 1) + d.max_parallel + "\n";
  s += "#SBATCH --ntasks=1\n";
  s += "#SBATCH --cpus-per-task=" + std::to_string(d.cpus_per_task) + "\n";
  s += "#SBATCH --mem=" + d.mem + "\n";
  s += "#SBATCH --time=" + d.time + "\n";
  if (!d.partition.empty()) s += "#SBATCH --partition=" + d.partition + "\n";
  if (!d.account.empty()) s += "#SBATCH --account=" + d.account + "\n";
  s += "#SBATCH --output=" + d.out_dir + "/logs/shard-%a.out\n";
  s += "set -u\n";
  s += "export OMP_NUM_THREADS=1\n";
  s += "shard=\"${SLURM_ARRAY_TASK_ID:?run this script with sbatch}\"\n";
  // N is fixed here, not SLURM_ARRAY_TASK_COUNT: a resubmission of some shards (--array=3,7)
  // must still cut the sweep into the same N shards.
  s += shellQuoted(d.parksim_exe) + " sweep " + shellQuoted(d.spec_path) + " --shard \"$shard/" +
       n + "\" --workers \"${SLURM_CPUS_PER_TASK:-" + std::to_string(d.cpus_per_task) +
       "}\" --out " + shellQuoted(d.out_dir) + "/shards/\"$shard\" --progress\n";
  s += "rc=$?\n";
  s += "# 1 = some episodes missed their tolerance: results, not a failed task.\n";
  s += "if [ \"$rc\" -le 1 ]; then exit 0; fi\n";
  s += "exit \"$rc\"\n";
  return s;
}

}  // namespace parksim
