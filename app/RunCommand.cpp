// parksim run WORLD: plan (or load a plan), drive it in the Bullet simulation, measure, and
// optionally film it. Writes DIR/trajectory.csv and DIR/plan.json (as `parksim plan`),
// DIR/executed.csv, DIR/metrics.json, and with --frames DIR/frames/*.png and the figures in
// DIR/figures/ (--video, --gif: DIR/episode.mp4, DIR/episode.gif). Exit status: 0 when the robot
// ends within the world's goal tolerance and the default TrackingTolerance holds (no contact,
// tracking error <= 5 mm, ...); 1 otherwise, or when planning fails, with a one-line reason on
// stderr; 2 on bad input.

#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>

#include "app/Command.h"
#include "app/FigureInputs.h"
#include "app/OptionChecks.h"
#include "app/OutputDir.h"
#include "app/PlanOutput.h"
#include "app/TerminalText.h"
#include "parksim/collision/BulletCollisionWorld.h"
#include "parksim/core/AtomicFile.h"
#include "parksim/core/Error.h"
#include "parksim/renders/Figures.h"
#include "parksim/renders/FrameRecorder.h"
#include "parksim/scenario/ScenarioReader.h"
#include "parksim/sim/Episode.h"
#include "parksim/sim/EpisodeFiles.h"
#include "parksim/sim/TrackingTolerance.h"

namespace parksim::app {

namespace {

// planSummary's keys with a plan_ prefix; nested objects flattened as plan_<key>.<sub>.
// Arrays (the RRT* cost history) stay in plan.json: metrics.json is flat.
void addPlanKeys(nlohmann::json& metrics, const nlohmann::json& summary) {
  for (const auto& [key, value] : summary.items()) {
    if (value.is_array()) continue;
    if (value.is_object()) {
      for (const auto& [sub, inner] : value.items()) metrics["plan_" + key + "." + sub] = inner;
    } else {
      metrics["plan_" + key] = value;
    }
  }
}

// For --plan FILE: the statistics a trajectory carries by itself.
nlohmann::json planFileSummary(const std::string& path, const Scenario& scenario,
                               const Trajectory& plan) {
  const Pose2& end = plan.points.back().pose;
  return {
      {"source", path},
      {"path_length_m", plan.pathLength(scenario.robot)},
      {"duration_s", plan.duration()},
      {"cusps", plan.cusps(scenario.robot)},
      {"final_pos_err_m", positionDistance(end, scenario.goal.pose)},
      {"final_heading_err_deg", radToDeg(headingDistance(end, scenario.goal.pose))},
  };
}

// A plan file must start where the world starts (within 1 mm and 0.5 deg, the planner's own
// goal tolerance); anything else is a plan for another world.
Trajectory loadPlanFile(const std::string& path, const Scenario& scenario) {
  Trajectory plan = readTrajectoryCsv(path);
  const Pose2& first = plan.points.front().pose;
  if (positionDistance(first, scenario.start) > 0.001 ||
      headingDistance(first, scenario.start) > degToRad(0.5)) {
    char text[256];
    std::snprintf(text, sizeof text,
                  "%s: the plan starts at (%.4f, %.4f, %.2f deg), not at the world's start "
                  "(%.4f, %.4f, %.2f deg)",
                  path.c_str(), first.x, first.y, radToDeg(first.theta), scenario.start.x,
                  scenario.start.y, radToDeg(scenario.start.theta));
    throw Error(text);
  }
  return plan;
}

// Empty when the episode succeeded; otherwise the one line that says why.
std::string failureReason(const Scenario& scenario, const EpisodeMetrics& m) {
  char text[320];
  if (m.contacts > 0) {
    std::snprintf(text, sizeof text, "touched %s at %.3f s (%d contact event%s)",
                  m.first_contact_body.c_str(), m.first_contact_t_s, m.contacts,
                  m.contacts == 1 ? "" : "s");
    return text;
  }
  if (!m.goal_reached) {
    std::snprintf(text, sizeof text,
                  "goal not reached: ended %.3f mm / %.3f deg from the goal (tolerance %.3f mm / "
                  "%.3f deg)",
                  m.goal_pos_err_m * 1e3, m.goal_heading_err_deg,
                  scenario.goal.position_tolerance_m * 1e3,
                  radToDeg(scenario.goal.heading_tolerance_rad));
    return text;
  }
  const std::vector<std::string> violations = checkTracking(TrackingTolerance{}, m);
  if (!violations.empty()) return "tracking tolerance not met: " + joinViolations(violations);
  return {};
}

FrameInput frameInput(const EpisodeSample& sample) {
  FrameInput in;
  in.t_s = sample.tracking.t_s;
  in.pose = sample.tracking.pose;
  in.reference = sample.tracking.reference;
  in.position_error_m = sample.tracking.pos_err_m;
  in.heading_error_rad = sample.tracking.heading_err_rad;
  in.obstacle_poses = sample.obstacles;
  in.contacts = sample.contacts;
  return in;
}

}  // namespace

CommandRunner setupRunCommand(CLI::App& sub) {
  struct Options {
    std::string world;
    std::string out = "out";
    std::string tracking = "closed";
    std::string plan_file;
    PlanCliOptions plan;
    bool frames = false;
    bool video = false;
    bool gif = false;
    double fps = 30.0;
    std::string size = "640x480";
    std::string view = "top";
  };
  auto opt = std::make_shared<Options>();
  sub.add_option("world", opt->world, "world file (YAML, see docs/world-format.md)")->required();
  opt->plan.addTo(sub);
  sub.add_option("--tracking", opt->tracking,
                 "closed: planned wheel speeds plus pose feedback; open: planned wheel speeds only")
      ->capture_default_str()
      ->check(CLI::IsMember({"closed", "open"}));
  sub.add_option("--plan", opt->plan_file,
                 "drive this trajectory.csv instead of planning (it must start at the world's "
                 "start)");
  sub.add_option("--out", opt->out, "output directory")->capture_default_str();
  sub.add_flag("--frames", opt->frames,
               "film the episode (OUT/frames/000000.png, ...) and draw the figures (OUT/figures/)");
  sub.add_flag("--video", opt->video, "also OUT/episode.mp4 (needs ffmpeg; implies --frames)");
  sub.add_flag("--gif", opt->gif, "also OUT/episode.gif (needs ffmpeg; implies --frames)");
  sub.add_option("--fps", opt->fps, "frames per second of simulated time")
      ->capture_default_str()
      ->check(realIn(0.0, 1000.0, true));
  sub.add_option("--size", opt->size, "size of one view, WxH pixels")->capture_default_str();
  sub.add_option("--view", opt->view, "top, 3d or both (side by side)")
      ->capture_default_str()
      ->check(CLI::IsMember({"top", "3d", "both"}));

  return [opt] {
    const Scenario scenario = loadScenario(opt->world);
    ExecutionDef exec;
    exec.tracking = trackingModeFromString(opt->tracking);
    const bool film = opt->frames || opt->video || opt->gif;
    FrameDef frame_def;
    if (film) {  // bad film options fail before anything is planned or written
      const ImageSize size = parseImageSize(opt->size);
      frame_def.fps = opt->fps;
      frame_def.width_px = size.width_px;
      frame_def.height_px = size.height_px;
      frame_def.view = frameViewFromString(opt->view);
      frame_def.video = opt->video;
      frame_def.gif = opt->gif;
    }
    // Every input is read and checked before DIR is touched: bad input leaves an earlier run's
    // outputs as they were. The outputs are written into a staging directory that replaces DIR
    // whole at the end (OutputDir), so DIR never mixes two runs.
    Trajectory plan;
    // Physics steps and frames are bounded by the plan's duration: checked once it is known.
    auto checkLimits = [&] {
      checkEpisodeLimits(scenario, plan, exec);
      if (film) checkFrameLimits(frame_def, plan.duration() + exec.max_stop_time_s);
    };
    if (!opt->plan_file.empty()) {
      plan = loadPlanFile(opt->plan_file, scenario);
      checkLimits();
    }
    const PlanSetup setup = opt->plan.toSetup(scenario);
    if (opt->plan_file.empty()) checkPlanningLimits(scenario, setup);

    OutputDir out(opt->out);
    const std::string& dir = out.path();
    const std::string shown_dir = printable(opt->out);

    nlohmann::json plan_summary;
    PlanFigure plan_figure;
    if (!opt->plan_file.empty()) {
      writeTrajectoryCsv(dir + "/trajectory.csv", plan, scenario.robot);
      plan_summary = planFileSummary(opt->plan_file, scenario, plan);
      plan_figure = {"file", "plan from " + opt->plan_file, plan, {}, {}};
    } else {
      const BulletCollisionWorld collision(scenario);
      const PlanResult result = planScenario(scenario, collision, setup);
      writePlanFiles(dir, scenario, setup, result);
      if (!result.solved()) {
        out.commit();
        std::fprintf(stderr, "parksim run: unsolved plan (%s): %s\n", toString(result.status),
                     printable(result.message).c_str());
        return 1;
      }
      plan = result.trajectory;
      checkLimits();
      plan_summary = planSummary(scenario, setup, result);
      if (film) plan_figure = planFigure(scenario, setup, result);
    }
    frame_def.out_dir = dir;

    std::unique_ptr<FrameRecorder> recorder;
    EpisodeObserver observer;
    if (film) {
      recorder = std::make_unique<FrameRecorder>(scenario, frame_def);
      recorder->setPlan(plan);
      observer = [&recorder](const EpisodeSample& sample) {
        recorder->addFrame(frameInput(sample));
      };
    }
    const EpisodeResult episode = runEpisode(scenario, plan, exec, observer, 1.0 / opt->fps);
    const EpisodeMetrics& m = episode.metrics;
    writeExecutedCsv(dir + "/executed.csv", episode.rows);
    nlohmann::json metrics = metricsToJson(m);
    metrics["world"] = scenario.source_path;
    metrics["scenario"] = scenario.name;
    addPlanKeys(metrics, plan_summary);
    writeJsonFile(dir + "/metrics.json", metrics);

    std::printf(
        "%s-loop episode on %s: tracking error max %.3f mm (rms %.3f mm), final %.3f mm / %.3f "
        "deg\nfinal pose %.3f mm / %.3f deg from the goal%s; %d contact event%s; %.2f s "
        "simulated in %.3f s (%.0fx real time)\nwrote %s/trajectory.csv, %s/executed.csv and "
        "%s/metrics.json\n",
        toString(m.tracking), printable(scenario.name).c_str(), m.max_pos_err_m * 1e3,
        m.rms_pos_err_m * 1e3, m.final_pos_err_m * 1e3, m.final_heading_err_deg,
        m.goal_pos_err_m * 1e3, m.goal_heading_err_deg,
        m.goal_reached ? " (within tolerance)" : " (outside tolerance)", m.contacts,
        m.contacts == 1 ? "" : "s", m.sim_time_s, m.wall_time_s,
        m.wall_time_s > 0.0 ? m.sim_time_s / m.wall_time_s : 0.0, shown_dir.c_str(),
        shown_dir.c_str(), shown_dir.c_str());
    if (recorder) {
      std::printf("%s\n", printableLines(out.shown(recorder->finish().message)).c_str());
      FigureInputs figures;
      figures.steering = steeringExample(scenario);
      figures.plans.push_back(std::move(plan_figure));
      figures.tracking = trackingSeries(episode.rows);
      const std::vector<std::string> written =
          writeFigures(scenario, figures, FigureDef{}, dir + "/figures");
      std::printf("%zu figures: %s/figures/\n", written.size(), shown_dir.c_str());
    }
    out.commit();
    const std::string failure = failureReason(scenario, m);
    if (!failure.empty()) {
      std::fprintf(stderr, "parksim run: %s\n", printable(failure).c_str());
      return 1;
    }
    return 0;
  };
}

}  // namespace parksim::app
