// bench_planning: plan quality and planning time against the best known (issue 18).
//
//   bench_planning [--configs default|previous|portfolio] [--seeds N] [--first-seed S]
//                  [--budget-scale K] [--anytime-s T] [--best FILE] [--out DIR] WORLD...
//
// default:   the library's defaults (PlanSetup{}), as every front-end plans.
// previous:  the defaults before issue 18 (hybrid-a-star, no smoothing, rows every 0.1 s, no
//            soft start), for before-and-after tables.
// portfolio: every planner, the tree planners with every exact steering, all smoothed, with K
//            times their default iteration budget and smoothing attempts (default K = 10), and
//            time-a-star anytime for T s (default 2): the "best known" of docs/benchmarks.md.
// Runs are interleaved seed by seed, so machine load hits every configuration alike. Every plan
// is checked by the exact path check (bench/planning/PathCheck.h). Writes DIR/bench.csv (one row
// per run, bench/planning/BenchCsv.h) and DIR/best_known.md, and prints the table: per world
// and configuration, the median duration over the best any configuration found (or the
// recorded best of --best FILE, lines "scenario,duration_s", when shorter) and over the
// free-space bound.

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "bench/planning/BenchCsv.h"
#include "bench/planning/BestKnown.h"
#include "bench/planning/ParksimRuns.h"
#include "parksim/collision/BulletCollisionWorld.h"
#include "parksim/core/io/AtomicFile.h"
#include "parksim/core/io/Error.h"
#include "parksim/planner/base/PlanScenario.h"
#include "parksim/scenario/world/ScenarioReader.h"

namespace {

using namespace parksim;

struct Options {
  std::string configs = "default";
  int seeds = 3;
  int first_seed = 1;
  int budget_scale = 10;
  double anytime_s = 2.0;
  std::string best_file;
  std::string out = "out/bench-planning";
  std::vector<std::string> worlds;
};

Options parse(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) throw Error(a + ": missing value");
      return argv[++i];
    };
    if (a == "--configs") {
      o.configs = value();
      if (o.configs != "default" && o.configs != "previous" && o.configs != "portfolio") {
        throw Error("--configs: expected default, previous or portfolio, got '" + o.configs + "'");
      }
    } else if (a == "--seeds") {
      o.seeds = std::stoi(value());
    } else if (a == "--first-seed") {
      o.first_seed = std::stoi(value());
    } else if (a == "--budget-scale") {
      o.budget_scale = std::stoi(value());
    } else if (a == "--anytime-s") {
      o.anytime_s = std::stod(value());
    } else if (a == "--best") {
      o.best_file = value();
    } else if (a == "--out") {
      o.out = value();
    } else if (!a.empty() && a[0] == '-') {
      throw Error("unknown option '" + a + "'");
    } else {
      o.worlds.push_back(a);
    }
  }
  if (o.worlds.empty()) throw Error("no world files given");
  if (o.seeds < 1 || o.budget_scale < 1 || !(o.anytime_s > 0.0)) {
    throw Error("--seeds and --budget-scale must be >= 1, --anytime-s > 0");
  }
  return o;
}

// The configurations to run on `scenario`, seed left to the caller.
std::vector<PlanSetup> configurations(const Options& o, const Scenario& scenario) {
  PlanSetup base;
  base.search.record_tree = false;
  if (o.configs == "default") return {base};
  if (o.configs == "previous") {
    PlanSetup previous = base;
    previous.planner = "hybrid-a-star";
    previous.search.smooth = false;
    previous.search.smoothing_attempts = 100;
    previous.steering_kind = SteeringKind::kReedsShepp;
    previous.timing_period_s = 0.1;
    previous.start_jerk_radps3 = 0.0;
    return {previous};
  }
  std::vector<PlanSetup> out;
  for (const std::string& name : builtInPlanners().names()) {
    if (plannerFor(name, scenario.robot) != name) continue;  // gives way to another planner
    const PlannerInfo& info = builtInPlanners().find(name).info;
    PlanSetup s = base;
    s.planner = name;
    s.search.smooth = true;
    s.search.max_iterations = o.budget_scale * defaultIterationBudget(info, scenario);
    s.search.smoothing_attempts *= o.budget_scale;
    if (!info.uses_steering) {
      out.push_back(s);
      continue;
    }
    for (SteeringKind steering : {SteeringKind::kBalkcomMason, SteeringKind::kReedsShepp,
                                  SteeringKind::kRotateTranslateRotate}) {
      s.steering_kind = steering;
      out.push_back(s);
    }
  }
  PlanSetup anytime = base;
  anytime.search.max_time_s = o.anytime_s;
  anytime.search.smoothing_attempts *= o.budget_scale;
  out.push_back(anytime);
  return out;
}

std::map<std::string, double> readBest(const std::string& path) {
  std::map<std::string, double> best;
  if (path.empty()) return best;
  std::ifstream in(path);
  if (!in) throw Error(path + ": cannot be read");
  std::string line;
  int n = 0;
  while (std::getline(in, line)) {
    ++n;
    if (line.empty() || line[0] == '#') continue;
    const std::size_t comma = line.find(',');
    if (comma == std::string::npos) {
      throw Error(path + ":" + std::to_string(n) + ": expected scenario,duration_s");
    }
    best[line.substr(0, comma)] = std::stod(line.substr(comma + 1));
  }
  return best;
}

int run(const Options& o) {
  std::vector<Scenario> scenarios;
  for (const std::string& w : o.worlds) scenarios.push_back(loadScenario(w));
  std::vector<bench::BenchRecord> records;
  for (std::size_t w = 0; w < scenarios.size(); ++w) {
    const Scenario& scenario = scenarios[w];
    const BulletCollisionWorld world(scenario);
    const std::vector<PlanSetup> configs = configurations(o, scenario);
    for (int seed = o.first_seed; seed < o.first_seed + o.seeds; ++seed) {
      for (const PlanSetup& config : configs) {
        bench::ParksimRunDef def;
        def.setup = config;
        def.setup.search.seed = static_cast<std::uint64_t>(seed);
        records.push_back(bench::runParksim(scenario, world, def));
        const bench::BenchRecord& r = records.back();
        std::fprintf(stderr, "%s %s %s %s seed %d: %s %.3f s in %.1f ms\n", r.scenario.c_str(),
                     r.planner.c_str(), r.space.c_str(), r.budget.c_str(), seed, r.status.c_str(),
                     r.duration_s, 1e3 * r.time_total_s);
      }
    }
  }
  const std::string table =
      bench::formatBestKnownTable(bench::compareWithBest(records, readBest(o.best_file)));
  std::filesystem::create_directories(o.out);
  bench::writeBenchCsv(o.out + "/bench.csv", records);
  writeFileAtomically(o.out + "/best_known.md", table);
  std::printf("%s\nwrote %s/bench.csv and %s/best_known.md\n", table.c_str(), o.out.c_str(),
              o.out.c_str());
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return run(parse(argc, argv));
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_planning: %s\n", e.what());
    return 2;
  }
}
