// parksim render WORLD: the study's figures for a world, planned but not driven.

#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "app/Command.h"
#include "app/PlanOutput.h"
#include "collision/BulletCollisionWorld.h"
#include "core/AtomicFile.h"
#include "core/Error.h"
#include "planner/MoveToPoseSteering.h"
#include "renders/Figures.h"
#include "renders/FrameRecorder.h"
#include "renders/TrackingPlot.h"
#include "scenario/ScenarioReader.h"

namespace parksim::app {

namespace {

std::string planCaption(const Scenario& scenario, const PlanSetup& setup,
                        const PlanResult& result) {
  char buf[256];
  if (result.solved()) {
    std::snprintf(buf, sizeof buf, "%s, %s (seed %llu): %d tree nodes, path %.2f m, %d cusp%s",
                  scenario.name.c_str(), toString(setup.planner.kind),
                  static_cast<unsigned long long>(setup.planner.seed), result.stats.tree_size,
                  result.trajectory.pathLength(scenario.robot),
                  result.trajectory.cusps(scenario.robot),
                  result.trajectory.cusps(scenario.robot) == 1 ? "" : "s");
  } else {
    std::snprintf(buf, sizeof buf, "%s, %s (seed %llu): %s after %d iterations",
                  scenario.name.c_str(), toString(setup.planner.kind),
                  static_cast<unsigned long long>(setup.planner.seed), toString(result.status),
                  result.stats.iterations);
  }
  return buf;
}

}  // namespace

CommandRunner setupRenderCommand(CLI::App& sub) {
  struct Options {
    std::string world;
    std::string out = "out";
    std::string size = "1200x800";
    std::string executed;
    double cspace_heading_deg = -60.0;
    int slices = 36;
    std::vector<double> steer_target;
    PlanCliOptions plan;
  };
  auto opt = std::make_shared<Options>();
  sub.add_option("world", opt->world, "world file (YAML, see docs/world-format.md)")->required();
  opt->plan.addTo(sub);
  sub.add_option("--size", opt->size, "figure size WxH in pixels")->capture_default_str();
  sub.add_option("--out", opt->out, "output directory; figures go to OUT/figures")
      ->capture_default_str();
  sub.add_option("--executed", opt->executed,
                 "executed.csv of an episode (columns t, pos_err, heading_err): adds the "
                 "tracking-error plot");
  sub.add_option("--cspace-heading", opt->cspace_heading_deg,
                 "heading of the C-space slice figure, degrees")
      ->capture_default_str();
  sub.add_option("--slices", opt->slices, "headings in the stacked C-space figure")
      ->capture_default_str()
      ->check(CLI::Range(1, 720));
  sub.add_option("--steer-target", opt->steer_target,
                 "target pose x y heading_deg of the steering figure (default: 0.3 m east and "
                 "0.3 m north of the start, heading 0)")
      ->expected(3);
  CLI::App* app = &sub;

  return [opt, app] {
    const Scenario scenario = loadScenario(opt->world);
    const ImageSize size = parseImageSize(opt->size);
    FigureDef def;
    def.width_px = size.width_px;
    def.height_px = size.height_px;
    def.cspace_heading_rad = degToRad(opt->cspace_heading_deg);
    def.cspace_slices = opt->slices;

    FigureInputs inputs;
    // Without --planner both of the study's planners are drawn (its Figs. 7 and 8).
    std::vector<std::string> planners = {opt->plan.planner};
    if (app->count("--planner") == 0) planners = {"rrt", "rrt-goal-connect"};
    const BulletCollisionWorld collision(scenario);
    ensureDirectory(opt->out);
    for (const std::string& name : planners) {
      PlanCliOptions options = opt->plan;
      options.planner = name;
      const PlanSetup setup = options.toSetup(scenario);
      const PlanResult result = planScenario(scenario, collision, setup);
      const std::string json_path = opt->out + "/plan_" + name + ".json";
      writeFileAtomically(json_path, planSummary(scenario, setup, result).dump(2) + "\n");
      std::printf("%s: %s (%s)\n", name.c_str(), toString(result.status), json_path.c_str());
      inputs.plans.push_back({name, planCaption(scenario, setup, result), result.trajectory,
                              result.waypoints, result.tree_edges});
    }

    SteeringExample steering;
    steering.start = scenario.start;
    steering.target =
        opt->steer_target.size() == 3
            ? Pose2{opt->steer_target[0], opt->steer_target[1], degToRad(opt->steer_target[2])}
            : Pose2{scenario.start.x + 0.3, scenario.start.y + 0.3, 0.0};
    const MoveToPoseSteering steer(scenario.robot);
    steering.fixed_horizon =
        steer.steer(steering.start, {}, steering.target, SteerMode::kFixedHorizon).trajectory;
    steering.to_goal =
        steer.steer(steering.start, {}, steering.target, SteerMode::kToGoal).trajectory;
    inputs.steering = steering;

    if (!opt->executed.empty()) inputs.tracking = readTrackingCsv(opt->executed);

    for (const std::string& path : writeFigures(scenario, inputs, def, opt->out + "/figures")) {
      std::printf("wrote %s\n", path.c_str());
    }
    return 0;
  };
}

}  // namespace parksim::app
