// A controller that is a process (usercode/CommandController.h) against the same law built in
// (docs/your-code.md, "Speed"). Wall time throughout: the process's time is the point.
// - BM_ControllerEpisode/<controller>: head_in under `lab` realism (50 Hz control ticks), noise
//   seed 1, one whole episode per iteration, process start and end included; 0: parksim's
//   tracking controller, 1: examples/commands/tracking_controller.py, the same law in Python, as
//   the command controller. Counters: rtf (simulated seconds per wall second) and ticks.
// - BM_CommandRoundTrip/<program>: one tick line out and the answer back, after a reset: 0 a
//   Python process answering "0 0" (the protocol and the pipes alone), 1 the tracking example.

#include <string>

#include <benchmark/benchmark.h>

#include "parksim/collision/BulletCollisionWorld.h"
#include "parksim/planner/base/PlanScenario.h"
#include "parksim/realism/RealismDef.h"
#include "parksim/scenario/world/ScenarioReader.h"
#include "parksim/sim/episode/Episode.h"
#include "parksim/usercode/CommandController.h"
#include "parksim/usercode/CommandLine.h"

namespace parksim {
namespace {

const Scenario& headIn() {
  static const Scenario s = loadScenario(std::string(PARKSIM_SOURCE_DIR) + "/worlds/head_in.yaml");
  return s;
}

const Trajectory& plan() {
  static const Trajectory t = [] {
    const BulletCollisionWorld checker(headIn());
    PlanSetup setup;
    setup.search.record_tree = false;
    return planScenario(headIn(), checker, setup).trajectory;
  }();
  return t;
}

std::vector<std::string> program(long which) {
  if (which == 0) {
    return {"python3", "-c",
            "import sys\nfor line in sys.stdin:\n"
            "    sys.stdout.write('ready\\n' if line.startswith('reset') else '0 0\\n')\n"
            "    sys.stdout.flush()\n"};
  }
  return {"python3", std::string(PARKSIM_SOURCE_DIR) + "/examples/commands/tracking_controller.py"};
}

EpisodeController controller(long which) {
  if (which == 0) return {};  // parksim's tracking controller
  const ParamMap params = {{kCommandParam, quoteCommandLine(program(1))}};
  return {commandControllerEntry().make(params), kCommandController, false};
}

void BM_ControllerEpisode(benchmark::State& state) {
  ExecutionDef def;
  def.realism = presetRealism("lab");
  def.noise_seed = 1;
  double sim_s = 0.0;
  long ticks = 0;
  for (auto _ : state) {
    const EpisodeResult r =
        runEpisode(headIn(), plan(), def, {}, 1.0 / 30.0, controller(state.range(0)));
    if (!r.metrics.controller_error.empty())
      state.SkipWithError(r.metrics.controller_error.c_str());
    sim_s += r.metrics.sim_time_s;
    ticks = static_cast<long>(r.metrics.sim_time_s * def.realism.control.rate_hz);
  }
  state.counters["rtf"] = benchmark::Counter(sim_s, benchmark::Counter::kIsRate);
  state.counters["ticks"] = static_cast<double>(ticks);
  state.SetLabel(state.range(0) == 0 ? "tracking, built in" : "tracking_controller.py, command");
}

void BM_CommandRoundTrip(benchmark::State& state) {
  CommandControllerDef def;
  def.command = program(state.range(0));
  CommandController c(def);
  c.reset({headIn(), plan(), 0.02, 0.0, true});
  ControllerInput in;
  in.pose = plan().points.front().pose;
  in.reference = in.pose;
  for (auto _ : state) {
    benchmark::DoNotOptimize(c.command(in));
    ++in.tick;
  }
  state.SetLabel(state.range(0) == 0 ? "answers 0 0" : "tracking_controller.py");
}

BENCHMARK(BM_ControllerEpisode)->Arg(0)->Arg(1)->UseRealTime()->Unit(benchmark::kMillisecond);
BENCHMARK(BM_CommandRoundTrip)->Arg(0)->Arg(1)->UseRealTime()->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace parksim

BENCHMARK_MAIN();
