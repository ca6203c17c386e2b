// A sweep run the way `parksim sweep SPEC --out OUT --workers N` runs it (prepareSweep,
// runSweepJob), with the choice `parksim sweep` makes for itself forced: its episodes on worker
// threads, or in worker processes (SweepRunnerDef::processes). Timed as a whole command by
// bench/plugin_overhead.sh, it separates the cost of worker processes (parksim's own controller
// on threads vs in processes) from the cost of a controller that comes from a plugin (parksim's
// own vs a plugin's copy of it, both in processes). docs/benchmarks.md, "Plugin overhead".
//
//   build/bench/bench_plugin_sweep SPEC WORKERS threads|processes OUT
//
// OUT must not hold a table yet (a resume would run nothing). Prints nothing; exit 0 when every
// episode has a row.

#include <cstdio>
#include <cstdlib>
#include <string>

#include "parksim/sweep/run/SweepJob.h"

int main(int argc, char** argv) {
  using namespace parksim;
  const std::string mode = argc == 5 ? argv[3] : "";
  if (mode != "threads" && mode != "processes") {
    std::fprintf(stderr, "usage: bench_plugin_sweep SPEC WORKERS threads|processes OUT\n");
    return 2;
  }
  try {
    const SweepPlan plan = prepareSweep(argv[1]);
    const bool user_code = sweepRunsUserCode(plan.episodes);
    if (user_code && mode == "threads") {
      throw Error("the spec runs user code: it runs in worker processes only");
    }
    SweepRunnerDef def;
    def.workers = std::atoi(argv[2]);
    def.processes = mode == "processes";
    const SweepJobResult r = runSweepJob(plan, Shard{}, argv[4], def, {}, {});
    return r.progress.done == r.episodes.size() ? 0 : 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_plugin_sweep: %s\n", e.what());
    return 2;
  }
}
