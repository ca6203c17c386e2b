// parksim plan WORLD: plan a parking manoeuvre and write trajectory.csv and plan.json: the
// episode pipeline without driving.

#include <algorithm>
#include <cstdio>
#include <string>

#include "app/Command.h"
#include "parksim/cli/ComponentOptions.h"
#include "parksim/cli/OutputDir.h"
#include "parksim/cli/PlanOptions.h"
#include "parksim/cli/Progress.h"
#include "parksim/cli/TerminalText.h"
#include "parksim/cli/WorldOptions.h"
#include "parksim/pipeline/EpisodePipeline.h"
#include "parksim/pipeline/EpisodeSettings.h"

namespace parksim::app {

namespace {

struct PlanOptions {
  std::string world;
  std::string out = "out";
  cli::PlanCliOptions plan;
  cli::PluginOptions plugins;
  cli::UserCodeOptions user_code;
  cli::WorldOverrideOptions world_overrides;
};

// Plans into the request's directory (not committed) and prints, in this process or a watched
// child.
int planCommand(const PlanOptions& o, EpisodeRequest& request, UserCodeWatch* watch,
                const OutputOptions& output) {
  request.watch = watch;
  const PlanSetup setup =
      resolvedPlanSetup(request.plan, request.world->scenario, componentsOf(request).planners);
  cli::Progress progress(std::string("planning (") + setup.planner + ")",
                         std::max(1, setup.search.max_iterations),
                         cli::progressWanted(output.progress, output.quiet));
  request.progress.plan = cli::planProgress(progress);
  const EpisodeOutcome outcome = runEpisodePipeline(request);
  progress.finish();
  if (!outcome.verdict.met()) {
    std::fprintf(stderr, "parksim plan: %s\n",
                 cli::printable(verdictLine(outcome.verdict)).c_str());
    return exitCodeFor(outcome.verdict.status);
  }
  const PlanResult& result = *outcome.plan;
  const RobotDef& robot = request.world->scenario.robot;
  const std::string dir = cli::printable(o.out);
  std::printf(
      "solved %s with %s (seed %llu): %d iterations, %d tree nodes, path %.3f m, %.1f s of "
      "motion, planned in %.2f ms\nwrote %s/trajectory.csv and %s/plan.json\n",
      cli::printable(request.world->scenario.name).c_str(), cli::printable(setup.planner).c_str(),
      static_cast<unsigned long long>(setup.search.seed), result.stats.iterations,
      result.stats.tree_size, result.trajectory.pathLength(robot), result.trajectory.duration(),
      1e3 * result.stats.times.total_s, dir.c_str(), dir.c_str());
  return kExitOk;
}

}  // namespace

CommandRunner setupPlanCommand(CLI::App& sub) {
  auto opt = std::make_shared<PlanOptions>();
  sub.add_option("world", opt->world, "world file (YAML, see docs/world-format.md)")->required();
  opt->plan.addTo(sub);
  opt->plugins.addTo(sub);
  opt->user_code.addTo(sub);
  opt->world_overrides.addTo(sub);
  sub.add_option("--out", opt->out, "output directory")->capture_default_str();

  return [opt](const OutputOptions& output) -> int {
    EpisodeRequest request;
    request.world = cli::loadWorldWith(opt->world, opt->world_overrides);
    request.plan = opt->plan.toSetup();
    request.components = opt->plugins.load();
    request.drive = false;
    request.limits = opt->user_code.limits;
    checkEpisodeRequest(request, {.limits = request.limits, .isolate = true});
    cli::OutputDir out(opt->out);
    request.out_dir = out.path();
    // A user's planner runs in a watched child: its crash or hang is a verdict.
    const std::optional<int> code =
        runWatched("parksim plan", runsUserCode(request), request.limits,
                   [&](UserCodeWatch* watch) { return planCommand(*opt, request, watch, output); });
    if (code) out.commit();
    return code.value_or(kExitUserCodeFailed);
  };
}

}  // namespace parksim::app
