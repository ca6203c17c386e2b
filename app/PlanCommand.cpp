// parksim plan WORLD: plan a parking manoeuvre and write trajectory.csv and plan.json.

#include <algorithm>
#include <cstdio>
#include <string>

#include "app/Command.h"
#include "app/OutputDir.h"
#include "app/Overrides.h"
#include "app/PlanOutput.h"
#include "app/Progress.h"
#include "app/TerminalText.h"
#include "parksim/collision/BulletCollisionWorld.h"
#include "parksim/scenario/ScenarioReader.h"

namespace parksim::app {

CommandRunner setupPlanCommand(CLI::App& sub) {
  struct Options {
    std::string world;
    std::string out = "out";
    PlanCliOptions plan;
    WorldOverrideOptions world_overrides;
  };
  auto opt = std::make_shared<Options>();
  sub.add_option("world", opt->world, "world file (YAML, see docs/world-format.md)")->required();
  opt->plan.addTo(sub);
  opt->world_overrides.addTo(sub);
  sub.add_option("--out", opt->out, "output directory")->capture_default_str();

  return [opt](const OutputOptions& output) -> int {
    const Scenario scenario = loadWorld(opt->world, opt->world_overrides);
    const PlanSetup setup = opt->plan.toSetup(scenario);
    checkPlanningLimits(scenario, setup);
    OutputDir out(opt->out);
    const BulletCollisionWorld collision(scenario);
    Progress progress(std::string("planning (") + toString(setup.planner.kind) + ")",
                      std::max(1, setup.planner.max_iterations),
                      progressWanted(output.progress, output.quiet));
    const PlanResult result = planScenario(scenario, collision, setup, planProgress(progress));
    progress.finish();
    writePlanFiles(out.path(), scenario, setup, result);
    out.commit();
    if (!result.solved()) {
      std::fprintf(stderr, "parksim plan: unsolved (%s): %s\n", toString(result.status),
                   printable(result.message).c_str());
      return kExitUnsolved;
    }
    std::printf(
        "solved %s with %s (seed %llu): %d iterations, %d tree nodes, path %.3f m, %.1f s of "
        "motion, planned in %.2f ms\nwrote %s/trajectory.csv and %s/plan.json\n",
        printable(scenario.name).c_str(), toString(setup.planner.kind),
        static_cast<unsigned long long>(setup.planner.seed), result.stats.iterations,
        result.stats.tree_size, result.trajectory.pathLength(scenario.robot),
        result.trajectory.duration(), 1e3 * result.stats.times.total_s, printable(opt->out).c_str(),
        printable(opt->out).c_str());
    return 0;
  };
}

}  // namespace parksim::app
