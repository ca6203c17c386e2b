// parksim run WORLD: plan (or load a plan), drive it in the Bullet simulation, measure, and
// optionally film it. Writes DIR/trajectory.csv and DIR/plan.json (as `parksim plan`),
// DIR/executed.csv, DIR/metrics.json, and with --frames DIR/frames/*.png and the figures in
// DIR/figures/ (--figures chooses them, also without --frames; --video, --gif:
// DIR/episode.mp4, DIR/episode.gif). Exit status: 0 when the robot
// ends within the world's goal tolerance and the default TrackingTolerance holds (no contact,
// tracking error <= 5 mm, ...); 4 when it does not and 1 when planning fails, each with a
// one-line reason on stderr; 2 on bad input (app/Command.h lists the exit codes).

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>

#include "app/Command.h"
#include "app/FigureInputs.h"
#include "app/GlBackendOption.h"
#include "app/OptionChecks.h"
#include "app/OutputDir.h"
#include "app/Overrides.h"
#include "app/PlanOutput.h"
#include "app/Progress.h"
#include "app/TerminalText.h"
#include "app/Validators.h"
#include "parksim/collision/BulletCollisionWorld.h"
#include "parksim/core/AtomicFile.h"
#include "parksim/core/Error.h"
#include "parksim/core/NumberFormat.h"
#include "parksim/core/Provenance.h"
#include "parksim/renders/EpisodeFrames.h"
#include "parksim/renders/Figures.h"
#include "parksim/scenario/RealismReader.h"
#include "parksim/scenario/ScenarioReader.h"
#include "parksim/realism/Distribution.h"
#include "parksim/sim/Episode.h"
#include "parksim/sim/EpisodeFiles.h"
#include "parksim/sim/TrackingTolerance.h"

namespace parksim::app {

namespace {

// A plan file must start where the world starts (within 1 mm and 0.5 deg, the planner's own
// goal tolerance); anything else is a plan for another world.
Trajectory loadPlanFile(const std::string& path, const Scenario& scenario) {
  Trajectory plan = readTrajectoryCsv(path);
  const Pose2& first = plan.points.front().pose;
  if (positionDistance(first, scenario.start) > 0.001 ||
      headingDistance(first, scenario.start) > degToRad(0.5)) {
    auto pose = [](const Pose2& p) {
      return "(" + formatFixed(p.x, 4) + ", " + formatFixed(p.y, 4) + ", " +
             formatFixed(radToDeg(p.theta), 2) + " deg)";
    };
    throw Error(path + ": the plan starts at " + pose(first) + ", not at the world's start " +
                pose(scenario.start));
  }
  return plan;
}

// Empty when the episode succeeded; otherwise the one line that says why.
std::string failureReason(const Scenario& scenario, const EpisodeMetrics& m,
                          const TrackingTolerance& tolerance) {
  if (m.contacts > 0) {
    return "touched " + m.first_contact_body + " at " + formatFixed(m.first_contact_t_s, 3) +
           " s (" + std::to_string(m.contacts) + " contact event" + (m.contacts == 1 ? ")" : "s)");
  }
  if (!m.goal_reached) {
    return "goal not reached: ended " + formatFixed(m.goal_pos_err_m * 1e3, 3) + " mm / " +
           formatFixed(m.goal_heading_err_deg, 3) + " deg from the goal (tolerance " +
           formatFixed(scenario.goal.position_tolerance_m * 1e3, 3) + " mm / " +
           formatFixed(radToDeg(scenario.goal.heading_tolerance_rad), 3) + " deg)";
  }
  const std::vector<std::string> violations = checkTracking(tolerance, m);
  if (!violations.empty()) return "tracking tolerance not met: " + joinViolations(violations);
  return {};
}

// One realisation's keys in metrics.json (realisation.<i>.<key>) and the distributions.
struct RealisationRow {
  std::uint64_t noise_seed = 0;
  EpisodeMetrics metrics;
  bool success = false;
};

void addRealisations(nlohmann::json& j, const std::vector<RealisationRow>& rows) {
  std::vector<double> max_err;
  std::vector<double> goal_err;
  std::vector<double> goal_heading;
  std::vector<double> est_err;
  std::vector<double> contacts;
  std::vector<double> slip;
  int successes = 0;
  int reached = 0;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const EpisodeMetrics& m = rows[i].metrics;
    const std::string p = "realisation." + std::to_string(i) + ".";
    j[p + "noise_seed"] = rows[i].noise_seed;
    j[p + "max_pos_err_m"] = m.max_pos_err_m;
    j[p + "rms_pos_err_m"] = m.rms_pos_err_m;
    j[p + "goal_pos_err_m"] = m.goal_pos_err_m;
    j[p + "goal_heading_err_deg"] = m.goal_heading_err_deg;
    j[p + "max_est_pos_err_m"] = m.max_est_pos_err_m;
    j[p + "max_slip_mps"] = m.max_slip_mps;
    j[p + "contacts"] = m.contacts;
    j[p + "goal_reached"] = m.goal_reached;
    j[p + "success"] = rows[i].success;
    max_err.push_back(m.max_pos_err_m);
    goal_err.push_back(m.goal_pos_err_m);
    goal_heading.push_back(m.goal_heading_err_deg);
    est_err.push_back(m.max_est_pos_err_m);
    contacts.push_back(m.contacts);
    slip.push_back(m.max_slip_mps);
    successes += rows[i].success ? 1 : 0;
    reached += m.goal_reached ? 1 : 0;
  }
  const auto add = [&j](const std::string& key, const std::vector<double>& values) {
    const Distribution d = summarize(values);
    j["realisations." + key + ".median"] = d.median;
    j["realisations." + key + ".p95"] = d.p95;
    j["realisations." + key + ".max"] = d.max;
  };
  const auto n = static_cast<double>(rows.size());
  j["realisations.count"] = rows.size();
  add("max_pos_err_m", max_err);
  add("goal_pos_err_m", goal_err);
  add("goal_heading_err_deg", goal_heading);
  add("max_est_pos_err_m", est_err);
  add("contacts", contacts);
  add("max_slip_mps", slip);
  j["realisations.goal_reached_fraction"] = reached / n;
  j["realisations.success_fraction"] = successes / n;
}

}  // namespace

CommandRunner setupRunCommand(CLI::App& sub) {
  struct Options {
    std::string world;
    std::string out = "out";
    std::string tracking = "closed";
    std::string plan_file;
    PlanCliOptions plan;
    WorldOverrideOptions world_overrides;
    bool frames = false;
    std::string figures;  // empty: all with --frames, else none
    bool video = false;
    bool gif = false;
    double fps = 30.0;
    std::string size = "640x480";
    std::string view = "top";
    std::string realism;
    std::uint64_t noise_seed = 1;
    int realisations = 1;
    double min_success_fraction = 1.0;
    double max_tracking_error_mm = -1.0;
    double max_goal_error_mm = -1.0;
    double max_goal_heading_error_deg = -1.0;
    GlBackendOption gl_backend;
  };
  auto opt = std::make_shared<Options>();
  sub.add_option("world", opt->world, "world file (YAML, see docs/world-format.md)")->required();
  opt->plan.addTo(sub);
  opt->world_overrides.addTo(sub);
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
  addFiguresOption(sub, opt->figures,
                   "default: all with --frames, --video or --gif, else none; a list alone "
                   "draws those figures without filming");
  sub.add_flag("--video", opt->video, "also OUT/episode.mp4 (needs ffmpeg; implies --frames)");
  sub.add_flag("--gif", opt->gif, "also OUT/episode.gif (needs ffmpeg; implies --frames)");
  sub.add_option("--fps", opt->fps, "frames per second of simulated time")
      ->capture_default_str()
      ->check(realIn(0.0, 1000.0, true));
  sub.add_option("--size", opt->size, "size of one view, WxH pixels")->capture_default_str();
  sub.add_option("--view", opt->view, "top, 3d or both (side by side)")
      ->capture_default_str()
      ->check(CLI::IsMember({"top", "3d", "both"}));
  opt->gl_backend.addTo(sub);
  sub.add_option("--realism", opt->realism,
                 "robot model: ideal (default; idealised motors, true pose at 240 Hz), lab "
                 "(motors, mocap at 100 Hz with 60 ms latency, fused estimate), odometry "
                 "(encoders only); replaces the world's realism: section (docs/realism.md)")
      ->check(CLI::IsMember({"ideal", "lab", "odometry"}));
  sub.add_option("--noise-seed", opt->noise_seed,
                 "seed of the realism's random draws (calibration, motor gains, sensor noise), "
                 "independent of --seed")
      ->capture_default_str()
      ->check(unsigned64());
  sub.add_option("--realisations", opt->realisations,
                 "drive the plan N times under noise seeds S, S+1, ... and report the "
                 "distribution (files of the first)")
      ->capture_default_str()
      ->check(integerIn(1, 10000));
  sub.add_option("--min-success-fraction", opt->min_success_fraction,
                 "with --realisations: share of realisations that must succeed for exit 0")
      ->capture_default_str()
      ->check(realIn(0.0, 1.0));
  sub.add_option("--max-tracking-error-mm", opt->max_tracking_error_mm,
                 "tracking tolerance: largest error against the plan (default 5, or the world's "
                 "tolerance: section)")
      ->check(realIn(0.0, 1e6, true));
  sub.add_option("--max-goal-error-mm", opt->max_goal_error_mm,
                 "tracking tolerance: final distance from the goal (default 3)")
      ->check(realIn(0.0, 1e6, true));
  sub.add_option("--max-goal-heading-error-deg", opt->max_goal_heading_error_deg,
                 "tracking tolerance: final heading error against the goal (default 1.5)")
      ->check(realIn(0.0, 360.0, true));

  return [opt](const OutputOptions& output) -> int {
    const Scenario scenario = loadWorld(opt->world, opt->world_overrides);
    const WorldRealism world_realism = loadWorldRealism(opt->world);
    ExecutionDef exec;
    exec.tracking = trackingModeFromString(opt->tracking);
    // --realism replaces the world's section; without either the robot is ideal.
    if (!opt->realism.empty()) {
      exec.realism = presetRealism(opt->realism);
    } else if (world_realism.has_realism) {
      exec.realism = world_realism.realism;
    }
    exec.noise_seed = opt->noise_seed;
    TrackingTolerance tolerance = world_realism.tolerance;
    if (opt->max_tracking_error_mm > 0.0)
      tolerance.max_pos_err_m = 1e-3 * opt->max_tracking_error_mm;
    if (opt->max_goal_error_mm > 0.0) tolerance.goal_pos_err_m = 1e-3 * opt->max_goal_error_mm;
    if (opt->max_goal_heading_error_deg > 0.0) {
      tolerance.goal_heading_err_deg = opt->max_goal_heading_error_deg;
    }
    const bool film = opt->frames || opt->video || opt->gif;
    FigureDef figure_def;
    figure_def.figures = opt->figures.empty() ? (film ? FigureSelection::all() : FigureSelection{})
                                              : FigureSelection::parse(opt->figures);
    // The GL backend, checked before anything is written when frames or figures are drawn.
    if (film || !figure_def.figures.empty()) figure_def.context = opt->gl_backend.context();
    FrameDef frame_def;
    if (film) {  // bad film options fail before anything is planned or written
      const ImageSize size = parseImageSize(opt->size);
      frame_def.fps = opt->fps;
      frame_def.width_px = size.width_px;
      frame_def.height_px = size.height_px;
      frame_def.view = frameViewFromString(opt->view);
      frame_def.video = opt->video;
      frame_def.gif = opt->gif;
      frame_def.context = figure_def.context;
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
      plan_summary = trajectorySummary(scenario, plan);
      plan_summary["source"] = opt->plan_file;
      plan_figure = {"file", "plan from " + opt->plan_file, plan, {}, {}};
    } else {
      const BulletCollisionWorld collision(scenario);
      Progress progress(std::string("planning (") + toString(setup.planner.kind) + ")",
                        std::max(1, setup.planner.max_iterations),
                        progressWanted(output.progress, output.quiet));
      const PlanResult result = planScenario(scenario, collision, setup, planProgress(progress));
      progress.finish();
      writePlanFiles(dir, scenario, setup, result);
      if (!result.solved()) {
        out.commit();
        std::fprintf(stderr, "parksim run: unsolved plan (%s): %s\n", toString(result.status),
                     printable(result.message).c_str());
        return kExitUnsolved;
      }
      plan = result.trajectory;
      checkLimits();
      plan_summary = planSummary(scenario, setup, result);
      if (!figure_def.figures.empty()) plan_figure = planFigure(scenario, setup, result);
    }
    frame_def.out_dir = dir;

    std::unique_ptr<FrameRecorder> recorder;
    std::unique_ptr<Progress> frame_progress;
    EpisodeObserver observer;
    if (film) {
      recorder = std::make_unique<FrameRecorder>(scenario, frame_def);
      recorder->setPlan(plan);
      // One frame per 1/fps of simulated time over the plan (the episode may run a little longer).
      const long expected_frames = static_cast<long>(plan.duration() * opt->fps) + 1;
      frame_progress = std::make_unique<Progress>("frames", expected_frames,
                                                  progressWanted(output.progress, output.quiet));
      observer = [&recorder, &frame_progress, frames = 0L](const EpisodeSample& sample) mutable {
        recorder->addFrame(frameInput(sample));
        frame_progress->update(++frames);
      };
    }
    const EpisodeResult episode = runEpisode(scenario, plan, exec, observer, 1.0 / opt->fps);
    if (frame_progress) frame_progress->finish();
    const EpisodeMetrics& m = episode.metrics;
    // The same plan under the next noise seeds (no frames; their files are not kept).
    std::vector<RealisationRow> realisations;
    realisations.push_back({exec.noise_seed, m, failureReason(scenario, m, tolerance).empty()});
    for (int i = 1; i < opt->realisations; ++i) {
      ExecutionDef again = exec;
      again.noise_seed = exec.noise_seed + static_cast<std::uint64_t>(i);
      const EpisodeMetrics mi = runEpisode(scenario, plan, again).metrics;
      realisations.push_back(
          {again.noise_seed, mi, failureReason(scenario, mi, tolerance).empty()});
    }
    const bool realism_columns = exec.realism.active();
    writeExecutedCsv(dir + "/executed.csv", episode.rows, realism_columns);
    if (exec.realism.pose_sensor.enabled) {
      writeFileAtomically(dir + "/sensors.csv", sensorsCsv(episode.pose_samples, m.time_step_s));
    }
    nlohmann::json metrics = metricsToJson(m);
    const nlohmann::json provenance = provenanceToJson(buildProvenance());
    for (const auto& [key, value] : provenance.items()) {
      metrics["provenance." + key] = value;
    }
    if (recorder) metrics["provenance.gl"] = recorder->glDescription();
    metrics["world"] = scenario.source_path;
    metrics["scenario"] = scenario.name;
    metrics["tolerance.max_pos_err_m"] = tolerance.max_pos_err_m;
    metrics["tolerance.goal_pos_err_m"] = tolerance.goal_pos_err_m;
    metrics["tolerance.goal_heading_err_deg"] = tolerance.goal_heading_err_deg;
    addPlanKeys(metrics, plan_summary);
    if (opt->realisations > 1) addRealisations(metrics, realisations);
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
    if (realism_columns) {
      std::printf(
          "%s realism, noise seed %llu (%s estimate): estimate error max %.3f mm, wheel "
          "slip max %.1f mm/s, motor torque max %.4f N m%s\n",
          exec.realism.name.c_str(), static_cast<unsigned long long>(exec.noise_seed),
          m.estimator.c_str(), m.max_est_pos_err_m * 1e3, m.max_slip_mps * 1e3,
          m.max_motor_torque_nm,
          exec.realism.pose_sensor.enabled ? "; pose samples in sensors.csv" : "");
    }
    if (recorder) {
      std::printf("%s\n", printableLines(out.shown(recorder->finish().message)).c_str());
    }
    if (!figure_def.figures.empty()) {
      FigureInputs figures;
      figures.steering = steeringExample(scenario);
      figures.plans.push_back(std::move(plan_figure));
      figures.tracking = trackingSeries(episode.rows);
      const std::vector<std::string> written =
          writeFigures(scenario, figures, figure_def, dir + "/figures");
      std::printf("%zu figures: %s/figures/\n", written.size(), shown_dir.c_str());
    }
    out.commit();
    if (opt->realisations > 1) {
      std::vector<double> max_err;
      std::vector<double> goal_err;
      std::vector<double> est_err;
      std::vector<double> contacts;
      int reached = 0;
      int succeeded = 0;
      for (const RealisationRow& r : realisations) {
        max_err.push_back(r.metrics.max_pos_err_m * 1e3);
        goal_err.push_back(r.metrics.goal_pos_err_m * 1e3);
        est_err.push_back(r.metrics.max_est_pos_err_m * 1e3);
        contacts.push_back(r.metrics.contacts);
        reached += r.metrics.goal_reached ? 1 : 0;
        succeeded += r.success ? 1 : 0;
      }
      const auto line = [](const char* what, const std::vector<double>& v, const char* unit) {
        const Distribution d = summarize(v);
        std::printf("  %-26s median %8.3f  p95 %8.3f  max %8.3f %s\n", what, d.median, d.p95, d.max,
                    unit);
      };
      const int n = opt->realisations;
      std::printf("%d realisations (%s realism, noise seeds %llu..%llu):\n", n,
                  exec.realism.name.c_str(), static_cast<unsigned long long>(exec.noise_seed),
                  static_cast<unsigned long long>(exec.noise_seed + static_cast<unsigned>(n - 1)));
      line("max tracking error", max_err, "mm");
      line("final goal error", goal_err, "mm");
      line("max estimation error", est_err, "mm");
      line("contact events", contacts, "");
      std::printf(
          "  goal reached in %d of %d (%.0f %%); within the tracking tolerance in %d of %d\n",
          reached, n, 100.0 * reached / n, succeeded, n);
      if (static_cast<double>(succeeded) < opt->min_success_fraction * n - 1e-9) {
        for (const RealisationRow& r : realisations) {
          if (r.success) continue;
          std::fprintf(stderr,
                       "parksim run: %d of %d realisations failed; first (noise seed %llu): %s\n",
                       n - succeeded, n, static_cast<unsigned long long>(r.noise_seed),
                       printable(failureReason(scenario, r.metrics, tolerance)).c_str());
          break;
        }
        return kExitToleranceNotMet;
      }
      return kExitOk;
    }
    const std::string failure = failureReason(scenario, m, tolerance);
    if (!failure.empty()) {
      std::fprintf(stderr, "parksim run: %s\n", printable(failure).c_str());
      return kExitToleranceNotMet;
    }
    return kExitOk;
  };
}

}  // namespace parksim::app
