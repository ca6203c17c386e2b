// parksim-bench WORLD [WORLD...]: the planning benchmark, a program of its own beside the
// parksim command line (both stand on the library; neither includes the other). Runs every parksim
// planner over seeds 1..N per world and, with --ompl, OMPL's RRT, RRTConnect and RRT* (Reeds-Shepp
// and SE2) on the same Bullet footprint checker; checks every path with parksim's exact path check;
// writes DIR/bench.csv and DIR/summary.md and prints the tables (docs/benchmarks.md explains them).
// Runs are interleaved seed by seed, so a change in machine load hits every planner alike.
// Exit status: 0 when every run finished (unsolved runs are results, not errors), 2 on bad input.

#include <unistd.h>

#include <chrono>
#include <climits>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <memory>
#include <optional>
#include <string>

#include <vector>

#include <CLI/CLI.hpp>

#include "bench/ompl/OmplPlanners.h"
#include "bench/planning/BenchCsv.h"
#include "bench/planning/BenchSummary.h"
#include "bench/planning/ParksimRuns.h"
#include "parksim/cli/ComponentOptions.h"
#include "parksim/cli/OutputDir.h"
#include "parksim/cli/PlanOptions.h"
#include "parksim/cli/Program.h"
#include "parksim/cli/Progress.h"
#include "parksim/cli/TerminalText.h"
#include "parksim/cli/Validators.h"
#include "parksim/collision/BulletCollisionWorld.h"
#include "parksim/core/io/AtomicFile.h"
#include "parksim/core/io/Error.h"
#include "parksim/core/io/NumberFormat.h"
#include "parksim/core/system/Provenance.h"
#include "parksim/planner/base/PlanScenario.h"
#include "parksim/planner/tree/TreePlanner.h"
#include "parksim/results/reports/OmplLog.h"
#include "parksim/scenario/world/ScenarioReader.h"

namespace parksim::bench {
namespace {

using cli::integerIn;
using cli::printable;
using cli::printableLines;
using cli::realIn;

using Clock = std::chrono::steady_clock;

struct BenchOptions {
  std::vector<std::string> worlds;
  int seeds = 100;
  std::vector<std::string> planners;   // parksim planner names; empty: all
  cli::PluginOptions plugins;          // --plugin: plugins' planners join the list
  std::vector<std::string> steerings;  // parksim steering kinds; empty: all
  bool smooth = false;                 // also run every parksim planner with smoothing
  std::string max_iterations = "auto";
  double time_limit_s = 0.0;  // parksim first-solution runs: wall-time budget, 0 = none
  double anytime_s = 0.1;
  bool ompl = false;
  std::vector<std::string> ompl_planners = {"RRT", "RRTConnect", "RRTstar"};
  std::vector<std::string> ompl_spaces = {"reeds-shepp", "se2"};
  double budget_s = 1.0;
  double turning_radius_m = 0.1;
  double segment_m = 0.0005;
  std::string out = "out/bench";
  std::string ompl_log;
};

double loadAverage() {
  double load[1] = {0.0};
  return getloadavg(load, 1) == 1 ? load[0] : -1.0;
}

std::string hostName() {
  char name[256] = {};
  return gethostname(name, sizeof name - 1) == 0 ? name : "UNKNOWN";
}

std::string cpuInfo() {
  std::ifstream in("/proc/cpuinfo");
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("model name", 0) == 0) {
      return line.substr(line.find(':') + 2) + ", " +
             std::to_string(sysconf(_SC_NPROCESSORS_ONLN)) + " logical CPUs";
    }
  }
  return "";
}

// FILE for a single world; FILE with ".<scenario>" before its extension for several.
std::string logPathFor(const std::string& path, const std::string& scenario, bool several) {
  if (!several) return path;
  const std::size_t slash = path.find_last_of('/');
  const std::size_t dot = path.find_last_of('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) {
    return path + "." + scenario;
  }
  return path.substr(0, dot) + "." + scenario + path.substr(dot);
}

std::string settingsText(const BenchOptions& o) {
  return "seeds 1.." + std::to_string(o.seeds) + "; parksim: max_iterations " + o.max_iterations +
         ", time limit " + formatGeneral(o.time_limit_s) + " s, anytime budget " +
         formatGeneral(o.anytime_s) + " s; OMPL: " + (o.ompl ? "on" : "off") + ", time limit " +
         formatGeneral(o.budget_s) + " s, Reeds-Shepp turning radius " +
         formatGeneral(o.turning_radius_m) + " m, motion-check segment " +
         formatGeneral(o.segment_m) + " m, validity margin 0; exact path check at 0.2 mm, margin 0";
}

using cli::OutputOptions;

// What one bench runs: the option lists parsed, the worlds read, every budget checked.
struct BenchPlan {
  std::vector<std::string> planners;
  std::vector<SteeringKind> steerings;
  std::vector<bool> smoothing;
  std::vector<OmplPlanner> ompl_planners;
  std::vector<OmplSpace> ompl_spaces;
  std::vector<Scenario> scenarios;
  int max_iterations = kAutoIterations;
  std::shared_ptr<const Components> components;  // built-ins and plugins
};

// Parses and checks everything before anything runs: bad names, budgets or worlds fail first.
BenchPlan benchPlanFrom(const BenchOptions& o) {
  if (o.seeds < 1) throw Error("--seeds must be at least 1");
  BenchPlan b;
  b.components = o.plugins.load();
  const PlannerRegistry& registry = b.components->planners;
  if (o.planners.empty()) {
    // Every planner that runs with its defaults: not the command planner, which needs its
    // command line (--planners names planners; their parameters are not bench options).
    for (const std::string& name : registry.names()) {
      try {
        (void)registry.make(name, {});
      } catch (const Error&) {
        continue;
      }
      b.planners.push_back(name);
    }
  } else if (o.planners != std::vector<std::string>{"none"}) {  // "none": OMPL alone
    for (const std::string& name : o.planners) {
      (void)registry.find(name);  // an unknown name fails here, before any run
      b.planners.push_back(name);
    }
  }
  if (o.steerings.empty()) {
    b.steerings = allSteeringKinds();
  } else {
    for (const std::string& name : o.steerings) {
      b.steerings.push_back(steeringKindFromString(name));
    }
  }
  b.smoothing = {false};
  if (o.smooth) b.smoothing.push_back(true);
  if (o.ompl) {
    for (const std::string& name : o.ompl_planners) {
      b.ompl_planners.push_back(omplPlannerFromString(name));
    }
    for (const std::string& name : o.ompl_spaces) {
      b.ompl_spaces.push_back(omplSpaceFromString(name));
    }
  }
  b.max_iterations = cli::parseIterationBudget(o.max_iterations);
  for (const std::string& path : o.worlds) b.scenarios.push_back(loadScenario(path));
  for (const Scenario& s : b.scenarios) {
    for (SteeringKind steering : b.steerings) {
      PlanSetup setup;
      setup.steering_kind = steering;
      checkPlanningLimits(s, setup);
    }
  }
  return b;
}

// parksim's planners for one world and seed: every planner x steering x smoothing, the A*
// planners once per smoothing (they ignore the steering), anytime planners also at full time.
void runParksimPlanners(const BenchOptions& o, const BenchPlan& b, const Scenario& scenario,
                        const BulletCollisionWorld& world, int seed, const PathCheckDef& check,
                        std::vector<BenchRecord>& all) {
  for (std::size_t si = 0; si < b.steerings.size(); ++si) {
    for (const std::string& name : b.planners) {
      const PlannerInfo& info = b.components->planners.find(name).info;
      if (!info.uses_steering && si > 0) continue;
      // A planner that gives way to another for this world's drive (time-a-star and car-a-star,
      // plannerFor) would run that one again.
      if (plannerFor(name, scenario.robot) != name) continue;
      // A car steers with Reeds-Shepp curves whatever is asked (resolvedPlanSetup): once.
      if (info.uses_steering && scenario.robot.isCar() && si > 0) continue;
      for (bool smooth : b.smoothing) {
        ParksimRunDef def;
        def.setup.steering_kind = b.steerings[si];
        def.setup.planner = name;
        def.planners = &b.components->planners;
        def.setup.search.seed = static_cast<std::uint64_t>(seed);
        def.setup.search.max_iterations = b.max_iterations;
        def.setup.search.max_time_s = o.time_limit_s;
        def.setup.search.record_tree = false;
        def.setup.search.smooth = smooth;
        def.check = check;
        all.push_back(runParksim(scenario, world, def));
        // Planners that keep improving their path until their budget ends get a second,
        // time-budgeted run per seed for the path length they reach in --anytime-s.
        if (info.anytime) {
          def.setup.search.max_iterations = INT_MAX;
          def.setup.search.max_time_s = o.anytime_s;
          all.push_back(runParksim(scenario, world, def));
        }
      }
    }
  }
}

void runOmplPlanners(const BenchOptions& o, const BenchPlan& b, const Scenario& scenario,
                     const BulletCollisionWorld& world, int seed, const PathCheckDef& check,
                     std::vector<BenchRecord>& all) {
  for (OmplSpace space : b.ompl_spaces) {
    for (OmplPlanner planner : b.ompl_planners) {
      OmplRunDef def;
      def.planner = planner;
      def.space = space;
      def.seed = static_cast<std::uint32_t>(seed);
      def.time_limit_s = o.budget_s;
      // A car's curves are no tighter than it steers; lengths tuned for the study's robot are
      // taken in the robot's size (RobotDef::sizeScale: exactly 1 for the study's robot).
      def.turning_radius_m = scenario.robot.isCar()
                                 ? std::max(o.turning_radius_m, scenario.robot.minTurningRadius())
                                 : o.turning_radius_m;
      def.segment_m = o.segment_m * scenario.robot.sizeScale();
      all.push_back(runOmpl(scenario, world, def, check));
    }
  }
}

// summary.md: the run table, the phase table, parksim against OMPL, invalid paths and the load.
std::string benchSummary(const std::vector<BenchRecord>& all, double load_before,
                         double load_after) {
  const std::vector<GroupSummary> groups = summarize(all);
  std::string summary = "Built by " + versionLine(buildProvenance()) + ".\n\n## Runs\n\n" +
                        formatSummaryTable(groups);
  summary += "\n## Where parksim's planners spend their time (mean per run)\n\n" +
             formatPhaseTable(groups);
  const std::string comparison = formatComparison(groups);
  if (!comparison.empty()) summary += "\n## parksim vs OMPL\n\n" + comparison;
  std::string invalid;
  for (const BenchRecord& r : all) {
    if (r.solved && !r.valid) {
      invalid += "- " + r.library + " " + r.planner + " (" + r.space + ", " + r.budget + ") " +
                 r.scenario + " seed " + std::to_string(r.seed) + "\n";
    }
  }
  summary += invalid.empty()
                 ? "\nEvery solved path passed parksim's exact path check (0.2 mm, margin 0).\n"
                 : "\n## Paths that failed parksim's exact path check\n\n" + invalid;
  summary += "\nLoad average " + formatFixed(load_before, 2) + " at start, " +
             formatFixed(load_after, 2) + " at end.\n";
  return summary;
}

// One OMPL benchmark log per world (--ompl-log), for Planner Arena and ompl_benchmark_statistics.
void writeOmplLogs(const BenchOptions& o, const std::vector<Scenario>& scenarios,
                   const std::vector<BenchRecord>& all, const std::vector<double>& world_seconds,
                   const std::string& start_time) {
  for (std::size_t w = 0; w < scenarios.size(); ++w) {
    std::vector<BenchRecord> mine;
    for (const BenchRecord& r : all) {
      if (r.scenario == scenarios[w].name) mine.push_back(r);
    }
    OmplLogInfo info;
    info.experiment = "parksim_" + scenarios[w].name;
    info.host = hostName();
    info.start_time = start_time;
    info.setup = "world " + scenarios[w].source_path + "\n" + settingsText(o) + "\n" +
                 versionLine(buildProvenance()) + "\n";
    info.cpu_info = cpuInfo();
    info.time_limit_s = o.ompl ? std::max(o.budget_s, o.anytime_s) : o.anytime_s;
    info.runs_per_planner = o.seeds;
    info.total_s = world_seconds[w];
    const std::string path = logPathFor(o.ompl_log, scenarios[w].name, scenarios.size() > 1);
    writeFileAtomically(path, omplBenchmarkLog(info, mine));
    std::printf("wrote %s\n", path.c_str());
  }
}

int runBench(const BenchOptions& o, const OutputOptions& output) {
  const BenchPlan plan = benchPlanFrom(o);
  cli::OutputDir out(o.out);

  const double load_before = loadAverage();
  std::printf("parksim bench: %zu world(s), seeds 1..%d, load average %.2f at start\n",
              plan.scenarios.size(), o.seeds, load_before);
  std::printf("settings: %s\n", settingsText(o).c_str());
  std::fflush(stdout);

  std::vector<BenchRecord> all;
  std::vector<double> world_seconds;
  const std::string start_time = omplLogTimeNow();
  for (const Scenario& scenario : plan.scenarios) {
    // 0.2 mm for the study's robot (in proportion to a larger one's size), margin 0, with
    // clearance.
    PathCheckDef check;
    check.max_step_m *= scenario.robot.sizeScale();
    const BulletCollisionWorld world(scenario);
    const Clock::time_point t0 = Clock::now();
    cli::Progress progress(scenario.name + " seeds", o.seeds,
                           cli::progressWanted(output.progress, output.quiet));
    for (int seed = 1; seed <= o.seeds; ++seed) {
      runParksimPlanners(o, plan, scenario, world, seed, check, all);
      runOmplPlanners(o, plan, scenario, world, seed, check, all);
      progress.update(seed);
    }
    progress.finish();
    world_seconds.push_back(std::chrono::duration<double>(Clock::now() - t0).count());
  }
  const std::string summary = benchSummary(all, load_before, loadAverage());

  const std::string csv_path = o.out + "/bench.csv";
  writeBenchCsv(out.path() + "/bench.csv", all);
  writeFileAtomically(out.path() + "/summary.md", summary);
  out.commit();
  std::printf("\n%s\nwrote %s and %s/summary.md\n", printableLines(summary).c_str(),
              printable(csv_path).c_str(), printable(o.out).c_str());
  if (!o.ompl_log.empty()) writeOmplLogs(o, plan.scenarios, all, world_seconds, start_time);
  return 0;
}

void addOptions(CLI::App& sub, BenchOptions* opt, OutputOptions& output) {
  cli::addOutputFlags(sub, output, "also print the build (stderr)");
  sub.add_option("worlds", opt->worlds, "world files (YAML, see docs/world-format.md)")->required();
  sub.add_option("--seeds", opt->seeds, "runs per planner and world, with seeds 1..N")
      ->capture_default_str()
      ->check(integerIn(1, 100'000));
  sub.add_option("--planners", opt->planners,
                 "parksim planners, comma-separated (default: every planner that runs with its "
                 "defaults, the plugins' too; none: OMPL only)")
      ->delimiter(',');
  opt->plugins.addTo(sub);
  sub.add_option("--steering", opt->steerings,
                 "parksim steering functions, comma-separated (default: all)")
      ->delimiter(',');
  sub.add_flag("--smooth", opt->smooth,
               "also run every parksim planner with shortcut smoothing (planner name +smooth)");
  sub.add_option("--max-iterations", opt->max_iterations,
                 "iteration budget of parksim's first-solution runs (auto: scaled with the lot, "
                 "as for plan)")
      ->capture_default_str();
  sub.add_option("--time-limit", opt->time_limit_s,
                 "wall-time budget of parksim's first-solution runs, s (0: none)")
      ->capture_default_str()
      ->check(realIn(0.0, 3600.0));
  sub.add_option("--anytime-s", opt->anytime_s,
                 "wall-time budget of the extra run of parksim's anytime planners (RRT*), s")
      ->capture_default_str()
      ->check(realIn(0.0, 3600.0, true));
  sub.add_flag("--ompl", opt->ompl, "also run OMPL's planners on the same footprint checker");
  sub.add_option("--ompl-planners", opt->ompl_planners, "OMPL planners, comma-separated")
      ->delimiter(',')
      ->capture_default_str();
  sub.add_option("--ompl-spaces", opt->ompl_spaces,
                 "OMPL state spaces, comma-separated: reeds-shepp, se2")
      ->delimiter(',')
      ->capture_default_str();
  sub.add_option("--budget-s", opt->budget_s,
                 "OMPL's wall-time limit per run, s (RRT* improves its path until then)")
      ->capture_default_str()
      ->check(realIn(0.0, 3600.0, true));
  sub.add_option("--turning-radius", opt->turning_radius_m,
                 "Reeds-Shepp minimum turning radius for OMPL, m (a car's: at least its own)")
      ->capture_default_str()
      ->check(realIn(0.0, 1000.0, true));
  sub.add_option("--segment", opt->segment_m,
                 "longest motion OMPL's motion validator leaves unchecked (state-space "
                 "distance; times the robot's size over the study robot's 85 mm)")
      ->capture_default_str()
      ->check(realIn(1e-6, 1.0));
  sub.add_option("--out", opt->out, "output directory for bench.csv and summary.md")
      ->capture_default_str();
  sub.add_option("--ompl-log", opt->ompl_log,
                 "also write OMPL's benchmark log format here (one file per world: "
                 "FILE.<scenario>.log when there are several)");
}

}  // namespace

}  // namespace parksim::bench

int main(int argc, char** argv) {
  using namespace parksim;
  cli::startProgram();
  CLI::App app{"parksim-bench: benchmark parksim's planners, optionally against OMPL",
               "parksim-bench"};
  const std::string version = versionLine(buildProvenance());
  app.set_version_flag("--version", version, "print parksim's version and build, then exit");
  bench::BenchOptions options;
  cli::OutputOptions output;
  bench::addOptions(app, &options, output);
  if (const std::optional<int> ended = cli::parseCommandLine(app, argc, argv, "parksim-bench")) {
    return *ended;
  }
  return cli::runReportingErrors("parksim-bench", [&]() -> int {
    if (output.verbose) std::fprintf(stderr, "%s\n", version.c_str());
    if (output.quiet && std::freopen("/dev/null", "w", stdout) == nullptr)
      return cli::kExitInternal;
    return bench::runBench(options, output);
  });
}
