// Episode benchmark on the study worlds (docs/simulation.md, "Benchmark"):
// - BM_Simulate: the dynamics alone (Bullet steps, control, measurement) driving a fixed plan;
//   the `rtf` counter is simulated seconds per CPU second, the real-time factor.
// - BM_Episode: what `parksim run` does after reading the world: plan, simulate, metrics.
// Arguments: world (0 head_in, 1 parallel), tracking (0 closed, 1 open), solver iterations,
// solver (0: parksim's default, SimModelDef{}; 1: Bullet's own solver running every iteration,
// the model as it was before the solver work; 2: Bullet's own solver with the early exit; 3:
// the model as it was before issue 21's speed work, Bullet's row setup and GJK contacts, cold
// started (kExact); for before/after ratios in one binary).
// - BM_SimulateRealism: BM_Simulate under a realism preset (0 ideal, 1 lab, 2 odometry), closed
//   loop, noise seed 1: the real-time factors of the presets side by side (docs/realism.md).
// - BM_SimulateCrowded: head_in with N more parked robots 20 m or more away (ideal, closed):
//   what far parked robots cost per step (docs/realism.md).

#include <map>
#include <string>

#include <benchmark/benchmark.h>

#include "parksim/collision/BulletCollisionWorld.h"
#include "parksim/core/model/Geometry.h"
#include "parksim/planner/base/PlanScenario.h"
#include "parksim/results/episode/ExecutedFile.h"
#include "parksim/results/episode/JsonFile.h"
#include "parksim/results/episode/MetricsFile.h"
#include "parksim/scenario/world/ScenarioReader.h"
#include "parksim/sim/episode/Episode.h"

namespace parksim {
namespace {

const char* const kWorlds[] = {"head_in", "parallel"};

Scenario world(long index, long solver_iterations) {
  Scenario s =
      loadScenario(std::string(PARKSIM_SOURCE_DIR) + "/worlds/" + kWorlds[index] + ".yaml");
  s.physics.solver_iterations = static_cast<int>(solver_iterations);
  return s;
}

PlanSetup setup() {
  PlanSetup p;
  p.search.seed = 1;
  p.search.record_tree = false;
  return p;
}

const Trajectory& plannedOnce(long index) {
  static std::map<long, Trajectory> plans;
  auto it = plans.find(index);
  if (it == plans.end()) {
    const Scenario s = world(index, PhysicsDef{}.solver_iterations);
    const BulletCollisionWorld checker(s);
    it = plans.emplace(index, planScenario(s, checker, setup()).trajectory).first;
  }
  return it->second;
}

// Runs the episode once per benchmark iteration; counters: real-time factor, simulated seconds
// and the last episode's largest tracking error.
void simulate(benchmark::State& state, const Scenario& s, const Trajectory& plan,
              const ExecutionDef& def, const SimModelDef& model = {}) {
  double sim_s = 0.0;
  double max_err = 0.0;
  for (auto _ : state) {
    Episode episode(s, plan, def, model);
    while (!episode.finished()) episode.step();
    const EpisodeMetrics m = episode.metrics();
    sim_s += m.sim_time_s;
    max_err = m.max_pos_err_m;
    benchmark::DoNotOptimize(episode.rows().data());
  }
  state.counters["rtf"] = benchmark::Counter(sim_s, benchmark::Counter::kIsRate);
  state.counters["sim_s"] = sim_s / static_cast<double>(state.iterations());
  state.counters["max_err_mm"] = max_err * 1e3;
}

void BM_Simulate(benchmark::State& state) {
  const Scenario s = world(state.range(0), state.range(2));
  const Trajectory& plan = plannedOnce(state.range(0));
  if (plan.empty()) {
    state.SkipWithError("the plan is unsolved");
    return;
  }
  ExecutionDef def;
  def.tracking = state.range(1) == 0 ? TrackingMode::kClosed : TrackingMode::kOpen;
  SimModelDef model;
  if (state.range(3) >= 1) model.warm_start = false;
  if (state.range(3) == 1 || state.range(3) == 2) model.solver = SolverKernel::kBullet;
  if (state.range(3) == 1) model.solver_residual_threshold = 0.0;
  if (state.range(3) == 3) model.solver = SolverKernel::kExact;
  simulate(state, s, plan, def, model);
  state.SetLabel(std::string(kWorlds[state.range(0)]) +
                 (def.tracking == TrackingMode::kClosed ? " closed" : " open") +
                 (state.range(3) == 1   ? " bullet-reference"
                  : state.range(3) == 2 ? " bullet-solver-early-exit"
                  : state.range(3) == 3 ? " before-issue-21"
                                        : ""));
}

const char* const kPresets[] = {"ideal", "lab", "odometry"};

void BM_SimulateRealism(benchmark::State& state) {
  const Scenario s = world(state.range(0), PhysicsDef{}.solver_iterations);
  const Trajectory& plan = plannedOnce(state.range(0));
  ExecutionDef def;
  def.realism = presetRealism(kPresets[state.range(1)]);
  def.noise_seed = 1;
  simulate(state, s, plan, def);
  state.SetLabel(std::string(kWorlds[state.range(0)]) + " " + kPresets[state.range(1)]);
}

void BM_SimulateCrowded(benchmark::State& state) {
  Scenario s = world(0, PhysicsDef{}.solver_iterations);
  const Trajectory& plan = plannedOnce(0);
  for (long i = 0; i < state.range(0); ++i) {
    Obstacle o;
    o.name = "far_" + std::to_string(i);
    o.kind = ObstacleKind::kParkedRobot;
    o.box = footprintAt(s.robot, {20.0 + 0.2 * static_cast<double>(i % 100),
                                  20.0 + 0.2 * static_cast<double>(i / 100), 0.0});
    o.height_m = s.robot.height_m;
    s.obstacles.push_back(o);
  }
  simulate(state, s, plan, ExecutionDef{});
  state.SetLabel("head_in + " + std::to_string(state.range(0)) + " far parked robots");
}

void BM_Episode(benchmark::State& state) {
  const Scenario s = world(state.range(0), state.range(2));
  double sim_s = 0.0;
  for (auto _ : state) {
    const BulletCollisionWorld checker(s);
    const PlanResult plan = planScenario(s, checker, setup());
    if (!plan.solved()) {
      state.SkipWithError("the plan is unsolved");
      return;
    }
    const EpisodeResult r = runEpisode(s, plan.trajectory);
    const nlohmann::json metrics = metricsToJson(r.metrics);
    const std::string csv = executedCsv(r.rows);
    sim_s += r.metrics.sim_time_s;
    benchmark::DoNotOptimize(csv.data());
    benchmark::DoNotOptimize(metrics.size());
  }
  state.counters["sim_s"] = sim_s / static_cast<double>(state.iterations());
  state.SetLabel(kWorlds[state.range(0)]);
}

// PhysicsDef's default: at most 15 iterations, warm-started.
BENCHMARK(BM_Simulate)
    ->ArgNames({"world", "open", "iters", "ref"})
    ->ArgsProduct({{0, 1}, {0, 1}, {15}, {0}})
    ->Args({0, 0, 50, 1})
    ->Args({1, 0, 50, 1})
    ->Args({0, 0, 50, 2})
    ->Args({1, 0, 50, 2})
    ->Args({0, 0, 50, 3})
    ->Args({1, 0, 50, 3})
    ->Args({0, 0, 50, 0})
    ->Args({1, 0, 50, 0})
    ->Args({0, 0, 10, 0})
    ->Args({1, 0, 10, 0})
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SimulateRealism)
    ->ArgNames({"world", "preset"})
    ->ArgsProduct({{0, 1}, {0, 1, 2}})
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SimulateCrowded)
    ->ArgNames({"far_parked"})
    ->Args({0})
    ->Args({1000})
    ->Args({10000})
    ->Args({100000})
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Episode)
    ->ArgNames({"world", "open", "iters"})
    ->Args({0, 0, 15})
    ->Args({1, 0, 15})
    ->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace parksim

BENCHMARK_MAIN();
