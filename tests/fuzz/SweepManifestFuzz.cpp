// libFuzzer harness for the sweep.json reader (parseSweepManifest in
// parksim/sweep/shards/SweepManifest.h, read by sweep, merge, report and --slurm --missing): any
// bytes must give a manifest or a parksim::Error, never a JSON type error, an overflowing
// conversion, a crash or a hang; a manifest it accepts writes and reads back the same. Built and
// run by scripts/fuzz.sh.

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "parksim/core/io/Error.h"
#include "parksim/sweep/shards/SweepManifest.h"
#include "tests/fuzz/FuzzSupport.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view bytes(reinterpret_cast<const char*>(data), size);
  parksim::SweepManifest m;
  try {
    m = parksim::parseSweepManifest(bytes, "sweep.json");
  } catch (const parksim::Error&) {
    return 0;
  }
  if (m.shard.count < 1 || m.shard.index < 0 || m.shard.index >= m.shard.count) std::abort();
  if (m.slurm_shards < 0) std::abort();
  // Round trip through the writer.
  const std::string& dir = parksim::fuzz::scratchDir();
  try {
    parksim::writeSweepManifest(dir, m);
  } catch (const parksim::Error&) {
    return 0;  // text the JSON writer cannot hold (invalid UTF-8 in a name)
  }
  parksim::SweepManifest back;
  if (!parksim::readSweepManifest(dir, back)) std::abort();
  if (back.episode_ids != m.episode_ids || back.name != m.name ||
      back.slurm_shards != m.slurm_shards || back.shard.index != m.shard.index ||
      back.slurm_request.has_value() != m.slurm_request.has_value()) {
    std::abort();
  }
  if (m.slurm_request) {
    const parksim::SlurmDef& a = *m.slurm_request;
    const parksim::SlurmDef& b = *back.slurm_request;
    if (a.cpus_per_task < 1 || a.cpus_per_task != b.cpus_per_task || a.mem != b.mem ||
        a.time != b.time || a.partition != b.partition || a.account != b.account ||
        a.max_parallel != b.max_parallel) {
      std::abort();
    }
  }
  return 0;
}
