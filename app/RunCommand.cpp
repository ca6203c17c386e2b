// parksim run WORLD: plan (or load a plan), drive it in the Bullet simulation, measure, judge,
// and optionally film it: one call of the episode pipeline (parksim/pipeline/). Writes
// DIR/trajectory.csv and DIR/plan.json (as `parksim plan`), DIR/executed.csv (--record-format
// npz: DIR/executed.npz), DIR/metrics.json, and with --frames DIR/frames/*.png and the figures
// in DIR/figures/ (--figures chooses them, also without --frames; --video, --gif:
// DIR/episode.mp4, DIR/episode.gif); --junit FILE: a JUnit report (docs/ci.md). Exit status: the
// verdict's (exitCodeFor: 0 met, 1 unsolved plan, 4 tolerance not met) with its one-line reason
// on stderr; 2 on bad input (app/Command.h lists the exit codes).

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
#include "parksim/cli/Progress.h"
#include "parksim/cli/ReportFileOption.h"
#include "parksim/cli/TerminalText.h"
#include "parksim/cli/Validators.h"
#include "parksim/cli/WorldOptions.h"
#include "parksim/pipeline/EpisodePipeline.h"
#include "parksim/pipeline/EpisodeSettings.h"
#include "parksim/realism/Distribution.h"
#include "parksim/realism/RealismDef.h"
#include "parksim/renders/image/PngEncoder.h"
#include "parksim/report/Report.h"
#include "parksim/results/episode/TrajectoryFile.h"
#include "parksim/results/reports/JUnitReport.h"
#include "parksim/sweep/run/EpisodeRun.h"

namespace parksim::app {

namespace {

using cli::printable;

struct RunOptions {
  std::string world;
  std::string out = "out";
  std::string tracking = toString(kDefaultTracking);
  std::string plan_file;
  cli::PlanCliOptions plan;
  cli::PluginOptions plugins;
  cli::ControllerOptions controller;
  cli::UserCodeOptions user_code;
  cli::WorldOverrideOptions world_overrides;
  bool frames = false;
  std::string figures;  // empty: all with --frames, else none
  bool video = false;
  bool gif = false;
  double fps = FrameDef{}.fps;
  std::string size = "640x480";
  std::string view = "top";
  std::string png_compression = toString(FrameDef{}.png_compression);
  std::string realism = kDefaultRealism;
  std::uint64_t noise_seed = kDefaultNoiseSeed;
  int realisations = 1;
  double min_success_fraction = 1.0;
  double max_tracking_error_mm = -1.0;
  double max_goal_error_mm = -1.0;
  double max_goal_heading_error_deg = -1.0;
  cli::GlBackendOption gl_backend;
  std::string record_format = toString(RecordDef{}.format);
  std::string junit;
};

void addEpisodeOptions(CLI::App& sub, RunOptions& o) {
  using cli::integerIn;
  using cli::realIn;
  sub.add_option("--tracking", o.tracking,
                 "closed: planned wheel speeds plus pose feedback; open: planned wheel speeds only")
      ->capture_default_str()
      ->check(CLI::IsMember({"closed", "open"}));
  sub.add_option("--plan", o.plan_file,
                 "drive this trajectory.csv instead of planning (it must start at the world's "
                 "start)");
  sub.add_option("--realism", o.realism,
                 "robot model: world (the world's realism: section, else ideal), ideal "
                 "(idealised motors, true pose at 240 Hz), lab (motors, mocap at 100 Hz with 60 "
                 "ms latency, fused estimate), odometry (encoders only) (docs/realism.md)")
      ->capture_default_str()
      ->check(CLI::IsMember(realismChoices()));
  sub.add_option("--noise-seed", o.noise_seed,
                 "seed of the realism's random draws (calibration, motor gains, sensor noise), "
                 "independent of --seed")
      ->capture_default_str()
      ->check(cli::unsigned64());
  sub.add_option("--realisations", o.realisations,
                 "drive the plan N times under noise seeds S, S+1, ... and report the "
                 "distribution (files of the first)")
      ->capture_default_str()
      ->check(integerIn(1, kMaxRealisations));
  sub.add_option("--min-success-fraction", o.min_success_fraction,
                 "with --realisations: share of realisations that must succeed for exit 0")
      ->capture_default_str()
      ->check(realIn(0.0, 1.0));
  sub.add_option("--max-tracking-error-mm", o.max_tracking_error_mm,
                 "tracking tolerance: largest error against the plan (default 5, or the world's "
                 "tolerance: section)")
      ->check(realIn(0.0, 1e6, true));
  sub.add_option("--max-goal-error-mm", o.max_goal_error_mm,
                 "tracking tolerance: final distance from the goal (default 3)")
      ->check(realIn(0.0, 1e6, true));
  sub.add_option("--max-goal-heading-error-deg", o.max_goal_heading_error_deg,
                 "tracking tolerance: final heading error against the goal (default 1.5)")
      ->check(realIn(0.0, 360.0, true));
  sub.add_option("--record-format", o.record_format,
                 "executed and sensor rows as csv (executed.csv) or npz (executed.npz: NumPy's "
                 "archive, exact, a third of the bytes or less)")
      ->capture_default_str()
      ->check(CLI::IsMember({"csv", "npz"}));
  cli::addReportFileOption(sub, "--junit", o.junit,
                           "also write a JUnit XML report: one test case per realisation, its "
                           "verdict as the failure (docs/ci.md)");
}

void addFilmOptions(CLI::App& sub, RunOptions& o) {
  sub.add_flag("--frames", o.frames,
               "film the episode (OUT/frames/000000.png, ...) and draw the figures (OUT/figures/)");
  cli::addFiguresOption(sub, o.figures,
                        "default: all with --frames, --video or --gif, else none; a list alone "
                        "draws those figures without filming");
  sub.add_flag("--video", o.video, "also OUT/episode.mp4 (needs ffmpeg; implies --frames)");
  sub.add_flag("--gif", o.gif, "also OUT/episode.gif (needs ffmpeg; implies --frames)");
  sub.add_option("--fps", o.fps, "frames per second of simulated time")
      ->capture_default_str()
      ->check(cli::realIn(0.0, 1000.0, true));
  sub.add_option("--size", o.size, "size of one view, WxH pixels")->capture_default_str();
  sub.add_option("--view", o.view, "top, 3d or both (side by side)")
      ->capture_default_str()
      ->check(CLI::IsMember({"top", "3d", "both"}));
  sub.add_option("--png-compression", o.png_compression,
                 "frames' PNG compression: default (zlib level 1), fast (run-length: about "
                 "the same size on films, larger on busy images, ~60% of the encoding CPU), "
                 "stored (uncompressed, 3 bytes a pixel), small (stb's deflate and filters, as "
                 "the figures: ~15% smaller, ~10x more CPU, ~40x on films)")
      ->capture_default_str()
      ->check(CLI::IsMember({"default", "fast", "stored", "small"}));
  o.gl_backend.addTo(sub);
}

// The options as the pipeline's request: every field the user did not set keeps the library's
// default.
EpisodeRequest toRequest(const RunOptions& o) {
  EpisodeRequest r;
  r.world = cli::loadWorldWith(o.world, o.world_overrides);
  r.plan = o.plan.toSetup();
  r.components = o.plugins.load();
  r.controller = o.controller.name;
  r.controller_params = o.controller.paramMap();
  if (!o.plan_file.empty()) {
    r.given_plan = readTrajectoryCsv(o.plan_file, r.world->scenario.robot);
    r.given_plan_source = o.plan_file;
  }
  r.execution.tracking = trackingModeFromString(o.tracking);
  r.realism = o.realism;
  r.noise_seed = o.noise_seed;
  r.realisations = o.realisations;
  r.min_success_fraction = o.min_success_fraction;
  r.record.format = recordFormatFromString(o.record_format);
  if (o.max_tracking_error_mm > 0.0) r.tolerance.max_pos_err_m = 1e-3 * o.max_tracking_error_mm;
  if (o.max_goal_error_mm > 0.0) r.tolerance.goal_pos_err_m = 1e-3 * o.max_goal_error_mm;
  if (o.max_goal_heading_error_deg > 0.0) {
    r.tolerance.goal_heading_err_deg = o.max_goal_heading_error_deg;
  }
  const bool film = o.frames || o.video || o.gif;
  r.figures.figures = o.figures.empty() ? (film ? FigureSelection::all() : FigureSelection{})
                                        : FigureSelection::parse(o.figures);
  // The GL backend, checked before anything is written when frames or figures are drawn.
  if (film || !r.figures.figures.empty()) r.figures.context = o.gl_backend.context();
  if (film) {
    const ImageSize size = parseImageSize(o.size);
    r.film.when = FilmWhen::kAlways;
    r.film.frames.fps = o.fps;
    r.film.frames.width_px = size.width_px;
    r.film.frames.height_px = size.height_px;
    r.film.frames.view = frameViewFromString(o.view);
    r.film.frames.png_compression = pngCompressionFromString(o.png_compression);
    r.film.frames.video = o.video;
    r.film.frames.gif = o.gif;
    r.film.frames.context = r.figures.context;
  }
  return r;
}

// The file written whose name starts with `prefix` (the record's: "executed.csv" or ".npz").
std::string written(const EpisodeOutcome& out, const std::string& prefix) {
  for (const std::string& f : out.files) {
    if (f.rfind(prefix, 0) == 0) return f;
  }
  return prefix + "csv";
}

void printEpisode(const EpisodeOutcome& out, const std::string& dir) {
  const EpisodeMetrics& m = out.episode.metrics;
  std::printf(
      "%s-loop episode on %s: tracking error max %.3f mm (rms %.3f mm), final %.3f mm / %.3f "
      "deg\nfinal pose %.3f mm / %.3f deg from the goal%s; %d contact event%s; %.2f s "
      "simulated in %.3f s (%.0fx real time)\nwrote %s/trajectory.csv, %s/%s, "
      "%s/metrics.json and %s/report.html (open it in a browser)\n",
      toString(m.tracking), printable(out.world->scenario.name).c_str(), m.max_pos_err_m * 1e3,
      m.rms_pos_err_m * 1e3, m.final_pos_err_m * 1e3, m.final_heading_err_deg,
      m.goal_pos_err_m * 1e3, m.goal_heading_err_deg,
      m.goal_reached ? " (within tolerance)" : " (outside tolerance)", m.contacts,
      m.contacts == 1 ? "" : "s", m.sim_time_s, m.wall_time_s,
      m.wall_time_s > 0.0 ? m.sim_time_s / m.wall_time_s : 0.0, dir.c_str(), dir.c_str(),
      written(out, "executed.").c_str(), dir.c_str(), dir.c_str());
  const ExecutionDef& exec = out.execution;
  if (exec.realism.active()) {
    std::printf(
        "%s realism, noise seed %llu (%s estimate): estimate error max %.3f mm, wheel "
        "slip max %.1f mm/s, motor torque max %.4f N m%s\n",
        exec.realism.name.c_str(), static_cast<unsigned long long>(exec.noise_seed),
        m.estimator.c_str(), m.max_est_pos_err_m * 1e3, m.max_slip_mps * 1e3, m.max_motor_torque_nm,
        exec.realism.pose_sensor.enabled ? ("; pose samples in " + written(out, "sensors.")).c_str()
                                         : "");
  }
}

void printRealisations(const EpisodeOutcome& out) {
  std::vector<double> max_err;
  std::vector<double> goal_err;
  std::vector<double> est_err;
  std::vector<double> contacts;
  int reached = 0;
  for (const RealisationOutcome& r : out.realisations) {
    max_err.push_back(r.metrics.max_pos_err_m * 1e3);
    goal_err.push_back(r.metrics.goal_pos_err_m * 1e3);
    est_err.push_back(r.metrics.max_est_pos_err_m * 1e3);
    contacts.push_back(r.metrics.contacts);
    reached += r.metrics.goal_reached ? 1 : 0;
  }
  const auto line = [](const char* what, const std::vector<double>& v, const char* unit) {
    const Distribution d = summarize(v);
    std::printf("  %-26s median %8.3f  p95 %8.3f  max %8.3f %s\n", what, d.median, d.p95, d.max,
                unit);
  };
  const auto n = static_cast<int>(out.realisations.size());
  std::printf("%d realisations (%s realism, noise seeds %llu..%llu):\n", n,
              out.execution.realism.name.c_str(),
              static_cast<unsigned long long>(out.realisations.front().noise_seed),
              static_cast<unsigned long long>(out.realisations.back().noise_seed));
  line("max tracking error", max_err, "mm");
  line("final goal error", goal_err, "mm");
  line("max estimation error", est_err, "mm");
  line("contact events", contacts, "");
  std::printf("  goal reached in %d of %d (%.0f %%); within the tracking tolerance in %d of %d\n",
              reached, n, 100.0 * reached / n, out.realisationsMet(), n);
}

// The verdict's line on stderr when it is not met: the reason, after how many realisations
// failed when there were several.
void printVerdict(const EpisodeOutcome& out) {
  if (out.verdict.met()) return;
  std::string prefix;
  if (out.realisations.size() > 1) {
    const auto n = static_cast<int>(out.realisations.size());
    std::uint64_t seed = 0;
    for (const RealisationOutcome& r : out.realisations) {
      if (!r.verdict.met()) {
        seed = r.noise_seed;
        break;
      }
    }
    prefix = std::to_string(n - out.realisationsMet()) + " of " + std::to_string(n) +
             " realisations failed; first (noise seed " + std::to_string(seed) + "): ";
  }
  std::fprintf(stderr, "parksim run: %s%s\n", prefix.c_str(),
               printable(verdictLine(out.verdict)).c_str());
}

// Plans (or takes the plan), drives, writes into `out` (not committed) and prints: the episode
// as `parksim run` runs it, in this process or a watched child.
int runEpisodeCommand(const RunOptions& o, EpisodeRequest& request, UserCodeWatch* watch,
                      const cli::OutputDir& out, const OutputOptions& output) {
  request.watch = watch;
  const bool show = cli::progressWanted(output.progress, output.quiet);
  const Scenario& scenario = request.world->scenario;
  const PlanSetup setup = resolvedPlanSetup(request.plan, scenario, componentsOf(request).planners);
  cli::Progress planning(std::string("planning (") + setup.planner + ")",
                         std::max(1, setup.search.max_iterations), show && !request.given_plan);
  request.progress.plan = cli::planProgress(planning);
  std::unique_ptr<cli::Progress> frames;
  request.progress.frames = [&frames, show](long done, long expected) {
    if (!frames) frames = std::make_unique<cli::Progress>("frames", expected, show);
    frames->update(done);
  };
  const EpisodeOutcome outcome = runEpisodePipeline(request);
  planning.finish();
  if (frames) frames->finish();
  if (!o.junit.empty()) {
    writeJUnitFile(o.junit, episodesJUnit(realisationRecords(request, outcome),
                                          "parksim run " + scenario.name, rowGroupNameOf));
  }
  const std::string dir = printable(o.out);
  if (outcome.driven()) {
    printEpisode(outcome, dir);
    if (outcome.recording)
      std::printf("%s\n", cli::printableLines(out.shown(outcome.recording->message)).c_str());
    int figures = 0;
    for (const std::string& f : outcome.files) figures += f.rfind("figures/", 0) == 0 ? 1 : 0;
    if (figures > 0) std::printf("%d figures: %s/figures/\n", figures, dir.c_str());
    if (outcome.realisations.size() > 1) printRealisations(outcome);
  }
  printVerdict(outcome);
  return exitCodeFor(outcome.verdict.status);
}

}  // namespace

CommandRunner setupRunCommand(CLI::App& sub) {
  auto opt = std::make_shared<RunOptions>();
  sub.add_option("world", opt->world, "world file (YAML, see docs/world-format.md)")->required();
  opt->plan.addTo(sub);
  opt->plugins.addTo(sub);
  opt->controller.addTo(sub);
  opt->user_code.addTo(sub);
  opt->world_overrides.addTo(sub);
  sub.add_option("--out", opt->out, "output directory")->capture_default_str();
  addEpisodeOptions(sub, *opt);
  addFilmOptions(sub, *opt);

  return [opt](const OutputOptions& output) -> int {
    EpisodeRequest request = toRequest(*opt);
    // Every input is checked before --out is touched; the outputs go to a staging directory
    // that replaces --out whole at the end (OutputDir), so --out never mixes two runs.
    request.limits = opt->user_code.limits;
    checkEpisodeRequest(request, {.limits = request.limits, .isolate = true});
    cli::OutputDir out(opt->out);
    request.out_dir = out.path();
    // A user's planner or controller runs in a watched child: its crash or hang is a verdict.
    const std::optional<int> code = runWatched(
        "parksim run", runsUserCode(request), request.limits,
        [&](UserCodeWatch* watch) { return runEpisodeCommand(*opt, request, watch, out, output); });
    if (code) out.commit();
    return code.value_or(kExitUserCodeFailed);
  };
}

}  // namespace parksim::app
