// parksim render WORLD: the study's figures for a world, planned but not driven.

#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "app/Command.h"
#include "parksim/cli/ComponentOptions.h"
#include "parksim/cli/FiguresOption.h"
#include "parksim/cli/GlBackendOption.h"
#include "parksim/cli/OutputDir.h"
#include "parksim/cli/PlanOptions.h"
#include "parksim/cli/TerminalText.h"
#include "parksim/cli/Validators.h"
#include "parksim/cli/WorldOptions.h"
#include "parksim/core/io/AtomicFile.h"
#include "parksim/core/io/Error.h"
#include "parksim/pipeline/EpisodeFigures.h"
#include "parksim/pipeline/EpisodePipeline.h"
#include "parksim/pipeline/EpisodeSettings.h"
#include "parksim/renders/film/FrameRecorder.h"
#include "parksim/renders/plots/Figures.h"
#include "parksim/renders/plots/TrackingPlot.h"
#include "parksim/results/episode/JsonFile.h"
#include "parksim/results/episode/TrajectoryFile.h"
#include "parksim/usercode/CommandPlanner.h"

namespace parksim::app {

CommandRunner setupRenderCommand(CLI::App& sub) {
  struct Options {
    std::string world;
    std::string out = "out";
    std::string size = "1200x800";
    std::string executed;
    double cspace_heading_deg = -60.0;
    int slices = 36;
    std::vector<double> steer_target;
    std::string figures = "all";
    cli::PlanCliOptions plan;
    cli::PluginOptions plugins;
    cli::UserCodeOptions user_code;
    cli::WorldOverrideOptions world_overrides;
    cli::GlBackendOption gl_backend;
  };
  auto opt = std::make_shared<Options>();
  sub.add_option("world", opt->world, "world file (YAML, see docs/world-format.md)")->required();
  opt->plan.addTo(sub);
  opt->plugins.addTo(sub);
  opt->user_code.addTo(sub);
  opt->world_overrides.addTo(sub);
  // render draws both of the study's planners unless --planner names one: no single default.
  CLI::Option* planner = sub.get_option("--planner");
  planner->default_str("")->description(
      "draw only this planner's plan, " + planner->get_description() +
      " (default: rrt and rrt-goal-connect, the study's Figs. 7 and 8)");
  sub.add_option("--size", opt->size, "figure size WxH in pixels")->capture_default_str();
  sub.add_option("--out", opt->out, "output directory; figures go to OUT/figures")
      ->capture_default_str();
  sub.add_option(
      "--executed", opt->executed,
      "executed.csv or executed.npz of an episode (columns t, pos_err, heading_err): adds the "
      "tracking-error plot");
  sub.add_option("--cspace-heading", opt->cspace_heading_deg,
                 "heading of the C-space slice figure, degrees")
      ->capture_default_str()
      ->check(cli::realIn(-360.0, 360.0));
  sub.add_option("--slices", opt->slices, "headings in the stacked C-space figure")
      ->capture_default_str()
      ->check(cli::integerIn(1, 720));
  sub.add_option("--steer-target", opt->steer_target,
                 "target pose x y heading_deg of the steering figure (default: 0.3 m east and "
                 "0.3 m north of the start, heading 0)")
      ->expected(3)
      ->check(cli::realIn(-1e4, 1e4));
  opt->gl_backend.addTo(sub);
  cli::addFiguresOption(sub, opt->figures, "default: all")->capture_default_str();
  CLI::App* app = &sub;

  return [opt, app](const OutputOptions&) -> int {
    const std::shared_ptr<const World> world = cli::loadWorldWith(opt->world, opt->world_overrides);
    const Scenario& scenario = world->scenario;
    const ImageSize size = parseImageSize(opt->size);
    FigureDef def;
    def.width_px = size.width_px;
    def.height_px = size.height_px;
    def.cspace_heading_rad = degToRad(opt->cspace_heading_deg);
    def.cspace_slices = opt->slices;
    def.context = opt->gl_backend.context();
    def.figures = FigureSelection::parse(opt->figures);

    FigureInputs inputs;
    // Without --planner both of the study's planners are drawn (its Figs. 7 and 8).
    std::vector<std::string> planners = {opt->plan.planner};
    if (!opt->plan.planner_command.empty()) {
      planners = {kCommandPlanner};
    } else if (app->count("--planner") == 0) {
      planners = {"rrt", "rrt-goal-connect"};
    }
    // Every input is read and checked before --out is touched.
    std::vector<EpisodeRequest> requests;
    const std::shared_ptr<const Components> components = opt->plugins.load();
    bool user_code = false;
    for (const std::string& name : planners) {
      cli::PlanCliOptions options = opt->plan;
      options.planner = name;
      EpisodeRequest& r = requests.emplace_back();
      r.world = world;
      r.plan = options.toSetup();
      r.components = components;
      r.drive = false;
      r.limits = opt->user_code.limits;
      checkEpisodeRequest(r, {.limits = r.limits, .isolate = true});
      user_code = user_code || runsUserCode(r);
    }
    if (!opt->executed.empty()) inputs.tracking = readTrackingRecord(opt->executed);
    std::optional<Pose2> target;
    if (opt->steer_target.size() == 3) {
      target = Pose2{opt->steer_target[0], opt->steer_target[1], degToRad(opt->steer_target[2])};
    }

    cli::OutputDir out(opt->out);
    // A user's planner runs in a watched child: its crash or hang is a verdict.
    const std::optional<int> code =
        runWatched("parksim render", user_code, opt->user_code.limits, [&](UserCodeWatch* watch) {
          std::string report;
          for (std::size_t i = 0; i < planners.size(); ++i) {
            requests[i].watch = watch;
            const EpisodeOutcome outcome = runEpisodePipeline(requests[i]);
            // A user's planner that failed (planner_error) left nothing to draw; a plan that
            // failed its check (plan_invalid) is not drawn as a plan: the verdict, its exit
            // status, and nothing written. An unsolved plan is drawn (its tree).
            const EpisodeStatus status = outcome.verdict.status;
            if (status == EpisodeStatus::kPlannerError || status == EpisodeStatus::kPlanInvalid) {
              std::fprintf(stderr, "parksim render: %s\n",
                           cli::printable(verdictLine(outcome.verdict)).c_str());
              return exitCodeFor(status);
            }
            const std::string json_name = "/plan_" + planners[i] + ".json";
            writeFileAtomically(out.path() + json_name, jsonText(outcome.plan_summary));
            report += cli::printable(planners[i] + ": " + toString(outcome.plan->status) + " (" +
                                     opt->out + json_name + ")") +
                      "\n";
            inputs.plans.push_back(planFigure(scenario, outcome.plan_setup, *outcome.plan));
          }
          inputs.steering = steeringExample(scenario, target);
          for (const std::string& path :
               writeFigures(scenario, inputs, def, out.path() + "/figures")) {
            report += cli::printable("wrote " + out.shown(path)) + "\n";
          }
          std::fputs(report.c_str(), stdout);
          return 0;
        });
    if (code == kExitOk) out.commit();
    return code.value_or(kExitUserCodeFailed);
  };
}

}  // namespace parksim::app
