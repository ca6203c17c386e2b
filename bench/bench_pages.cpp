// What writing the pages costs, side by side with what it is written for (docs/pages.md):
//   BM_Episode/<world>       one episode through the pipeline, planned, driven at 240 Hz,
//                            no files (what `parksim run` does besides writing)
//   BM_EpisodePage/<world>   writing that episode's report.html
//   BM_SweepPage/<rows>      writing a sweep's index.html for a table of that many rows (the
//                            study's 120 rows repeated under new ids), from rows in memory
//   BM_SweepPageOfTable      the same for the table PARKSIM_BENCH_TABLE names (a results.jsonl,
//                            e.g. bench/pages/sweep_20k.yaml's): skipped when unset
// worlds: 0 head_in (the demo's episode), 1 big_lot (10 x 10 m, 300 boxes).
// Run: build/bench/bench_pages --benchmark_counters_tabular=true
// BM_EpisodePage's time over BM_Episode's is the share a page adds to a run without frames;
// bytes is the page's size.

#include <benchmark/benchmark.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "parksim/pages/EpisodePage.h"
#include "parksim/pages/SweepPage.h"
#include "parksim/pipeline/EpisodePipeline.h"
#include "parksim/results/tables/ResultsFile.h"
#include "parksim/scenario/world/World.h"

namespace parksim {
namespace {

namespace fs = std::filesystem;

const char* const kWorlds[] = {"head_in", "big_lot"};

std::shared_ptr<const World> world(int index) {
  static std::shared_ptr<const World> worlds[2];
  if (!worlds[index]) {
    worlds[index] = std::make_shared<const World>(
        loadWorld(std::string(PARKSIM_SOURCE_DIR) + "/worlds/" + kWorlds[index] + ".yaml"));
  }
  return worlds[index];
}

EpisodeOutcome episode(int index) {
  EpisodeRequest r;
  r.world = world(index);
  return runEpisodePipeline(r);
}

std::string scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / "parksim-bench-pages";
  fs::create_directories(dir);
  return (dir / name).string();
}

void BM_Episode(benchmark::State& state) {
  const int w = static_cast<int>(state.range(0));
  world(w);
  for (auto _ : state) benchmark::DoNotOptimize(episode(w));
  state.SetLabel(kWorlds[w]);
}

void BM_EpisodePage(benchmark::State& state) {
  const int w = static_cast<int>(state.range(0));
  const EpisodeOutcome out = episode(w);
  EpisodePage page;
  page.status = "met";
  page.plan = &out.trajectory;
  page.rows = out.episode.rows;
  page.metrics = &out.episode.metrics;
  page.tolerance = &out.tolerance;
  page.plan_summary = &out.plan_summary;
  const std::string path = scratch(std::string(kWorlds[w]) + ".html");
  for (auto _ : state) writeEpisodePage(path, out.world->scenario, page);
  state.counters["rows"] = static_cast<double>(out.episode.rows.size());
  state.counters["bytes"] = static_cast<double>(fs::file_size(path));
  state.SetLabel(kWorlds[w]);
}

// The study sweep's rows: its 120 episodes (results of `parksim sweep worlds/sweeps/study.yaml`
// in the form a row takes), repeated under new ids to `n` rows.
std::vector<nlohmann::ordered_json> studyRows(int n) {
  std::vector<nlohmann::ordered_json> rows;
  const char* planners[] = {"rrt", "rrt-goal-connect", "rrt-connect"};
  for (int i = 0; i < n; ++i) {
    nlohmann::ordered_json r;
    r["episode_id"] = "e" + std::to_string(1000000 + i);
    r["world"] = i % 2 ? "head_in" : "parallel";
    r["planner"] = planners[(i / 2) % 3];
    r["seed"] = i / 6 + 1;
    r["status"] = i % 30 == 7 ? "plan_failed" : "met";
    r["met_tolerance"] = i % 30 != 7;
    r["failure"] =
        i % 30 == 7 ? "unsolved plan (iteration_limit): no collision-free trajectory" : "";
    r["plan_iterations"] = 200 + (i * 37) % 1800;
    r["plan_tree_size"] = 100 + (i * 53) % 3000;
    r["plan_path_length_m"] = 1.5 + 1e-3 * ((i * 7919) % 1000);
    r["plan_duration_s"] = 25.0 + 1e-2 * ((i * 104729) % 3000);
    for (const char* key : {"max_pos_err_m", "rms_pos_err_m", "final_pos_err_m", "goal_pos_err_m",
                            "max_heading_err_deg", "goal_heading_err_deg"}) {
      r[key] = 1e-4 * (1.0 + ((i * 31 + key[1]) % 977) / 977.0);
    }
    r["contacts"] = 0;
    r["sim_time_s"] = 26.0 + 1e-2 * ((i * 7) % 300);
    r["steps"] = 6240 + (i * 13) % 720;
    r["plan_time_s"] = 1e-3 * (1 + (i * 17) % 50);
    r["episode_wall_s"] = 0.1 + 1e-3 * ((i * 19) % 100);
    r["world_hash"] = "0123456789abcdef";
    r["parksim_version"] = "0.3.0";
    rows.push_back(r);
  }
  return rows;
}

void sweepPage(benchmark::State& state, const std::vector<nlohmann::ordered_json>& rows) {
  SweepPage page;
  page.title = "bench";
  page.source = "out/bench";
  page.rows = &rows;
  page.axes = parameterColumns(rows);
  page.statuses = {"met", "plan_failed"};
  page.episodes_href = "../episodes";
  page.kept.assign(rows.size(), false);
  const std::string path = scratch("index.html");
  for (auto _ : state) writeSweepPage(path, page);
  state.counters["bytes"] = static_cast<double>(fs::file_size(path));
  state.counters["rows"] = static_cast<double>(rows.size());
}

void BM_SweepPage(benchmark::State& state) {
  sweepPage(state, studyRows(static_cast<int>(state.range(0))));
}

void BM_SweepPageOfTable(benchmark::State& state) {
  const char* table = std::getenv("PARKSIM_BENCH_TABLE");
  if (table == nullptr) {
    state.SkipWithError("PARKSIM_BENCH_TABLE names no results.jsonl");
    return;
  }
  sweepPage(state, readResultsJsonl(table));
}

BENCHMARK(BM_Episode)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_EpisodePage)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SweepPage)->Arg(120)->Arg(20000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SweepPageOfTable)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace parksim

BENCHMARK_MAIN();
