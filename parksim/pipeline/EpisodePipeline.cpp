#include "parksim/pipeline/EpisodePipeline.h"

#include <climits>
#include <memory>

#include "parksim/collision/BulletCollisionWorld.h"
#include "parksim/core/io/AtomicFile.h"
#include "parksim/core/io/Error.h"
#include "parksim/pipeline/EpisodeFigures.h"
#include "parksim/pipeline/EpisodeReport.h"
#include "parksim/pipeline/EpisodeSettings.h"
#include "parksim/results/episode/ExecutedFile.h"
#include "parksim/results/episode/JsonFile.h"
#include "parksim/results/episode/MetricsFile.h"
#include "parksim/results/episode/PlanFile.h"
#include "parksim/results/episode/TrajectoryFile.h"

namespace parksim {

namespace {

// Rows of realisations after the first and of a second, filmed drive are not kept: only the
// first and the last row are recorded.
constexpr int kFirstAndLastRowOnly = INT_MAX / 2;

// plan.json's content for a planner that gave no result (out.verdict: its planner_error): what
// was asked, why it failed, and whose code it was.
nlohmann::json plannerFailureSummary(const EpisodeRequest& request, const EpisodeOutcome& out) {
  const Components& components = componentsOf(request);
  const PlannerInfo& info = components.planners.find(out.plan_setup.planner).info;
  nlohmann::json j = failedPlanSummary(request.world->scenario, out.plan_setup,
                                       toString(out.verdict.status), out.verdict.reason);
  j["planner_origin"] = plannerOrigin(components, info, out.plan_setup.planner_params);
  return j;
}

// Plans, or takes the given plan. Sets the trajectory to drive, the plan's summary, and the
// verdict when there is nothing to drive: plan_failed when the planner found nothing,
// planner_error when a user's planner failed, plan_invalid when a plan parksim did not make
// fails its check (planScenario checks a planner's, this a given one's: PlanCheck.h).
void planStage(const EpisodeRequest& request, EpisodeOutcome& out) {
  const Scenario& scenario = request.world->scenario;
  const BulletCollisionWorld collision(scenario);
  if (request.given_plan) {
    out.trajectory = *request.given_plan;
    out.plan_summary = trajectorySummary(scenario, out.trajectory);
    if (!request.given_plan_source.empty()) out.plan_summary["source"] = request.given_plan_source;
    if (const std::optional<PlanViolation> v =
            checkPlan(scenario, collision, out.trajectory, out.plan_setup.validation)) {
      out.verdict = planInvalidVerdict(*v);
    }
    return;
  }
  const Components& components = componentsOf(request);
  const PlannerInfo& info = components.planners.find(out.plan_setup.planner).info;
  // Where the planner's own code runs, for a watching process (UserCodeIsolation.h); a command
  // stops its program at request.limits itself.
  UserCodeWatch* watch = info.trusted || info.own_process ? nullptr : request.watch;
  if (watch != nullptr) watch->enter(UserCodeWatch::Phase::kPlanner, info.name);
  try {
    out.plan = planScenario(scenario, collision, out.plan_setup, request.progress.plan,
                            components.planners, request.limits.planner_s);
  } catch (const UserCodeError& e) {
    out.verdict = userCodeVerdict(e);
    out.plan_summary = plannerFailureSummary(request, out);
    return;
  }
  if (watch != nullptr) watch->enter(UserCodeWatch::Phase::kParksim, "");
  out.plan_summary = planSummary(scenario, out.plan_setup, *out.plan);
  // What made the plan, recorded beside it: nothing else says which code it was.
  const std::string origin = plannerOrigin(components, info, out.plan_setup.planner_params);
  if (!origin.empty()) out.plan_summary["planner_origin"] = origin;
  // A plan that failed its check is kept to be shown (the episode's page), never driven.
  if (out.plan->solved() || out.plan->status == PlanStatus::kPlanInvalid) {
    out.trajectory = out.plan->trajectory;
  }
  if (!out.plan->solved()) out.verdict = planFailedVerdict(*out.plan);
}

// The controller of one realisation: a fresh one from the registry (closed loop).
EpisodeController controllerFor(const EpisodeRequest& request) {
  const ControllerEntry& entry = componentsOf(request).controllers.find(request.controller);
  const ControllerInfo& info = entry.info;
  UserCodeWatch* watch = info.trusted || info.own_process ? nullptr : request.watch;
  // Its constructor is its code too: watched like its commands.
  if (watch != nullptr) watch->enter(UserCodeWatch::Phase::kController, info.name);
  std::unique_ptr<Controller> controller = entry.make(request.controller_params);
  if (watch != nullptr) watch->enter(UserCodeWatch::Phase::kParksim, "");
  return {std::move(controller), info.name, info.trusted, watch, request.limits.controller_tick_s};
}

// A recorder filming into the request's directory, with the plan drawn.
std::unique_ptr<FrameRecorder> makeRecorder(const EpisodeRequest& request, const Trajectory& plan) {
  FrameDef def = request.film.frames;
  def.out_dir = request.out_dir;
  auto recorder = std::make_unique<FrameRecorder>(request.world->scenario, def);
  recorder->setPlan(plan);
  return recorder;
}

// Waits for the film, showing the frames written against all of them.
RecordingResult finishFilm(const EpisodeRequest& request, FrameRecorder& recorder) {
  if (!request.progress.frames) return recorder.finish();
  return recorder.finish(
      [&](long written) { request.progress.frames(written, recorder.frames()); });
}

// Drives the plan under one noise seed; `recorder` (optional) films it.
EpisodeResult drive(const EpisodeRequest& request, const Trajectory& plan,
                    const ExecutionDef& execution, FrameRecorder* recorder) {
  if (recorder == nullptr) {
    return runEpisode(request.world->scenario, plan, execution, {}, 1.0 / 30.0,
                      controllerFor(request));
  }
  const double fps = request.film.frames.fps;
  const long expected = static_cast<long>(plan.duration() * fps) + 1;
  const EpisodeObserver observer = [&](const EpisodeSample& sample) {
    recorder->addFrame(frameInput(sample));
    // Written, not handed over: the drawing may be far behind the simulation.
    if (request.progress.frames) request.progress.frames(recorder->framesWritten(), expected);
  };
  return runEpisode(request.world->scenario, plan, execution, observer, 1.0 / fps,
                    controllerFor(request));
}

// Every realisation, each judged; the first is kept whole (and filmed when asked).
void driveStage(const EpisodeRequest& request, const EpisodeSettings& settings,
                FrameRecorder* recorder, EpisodeOutcome& out) {
  const Scenario& scenario = request.world->scenario;
  out.execution = settings.execution;
  out.tolerance = settings.tolerance;
  out.episode = drive(request, out.trajectory, settings.execution, recorder);
  out.realisations.push_back({settings.execution.noise_seed, out.episode.metrics,
                              judgeEpisode(scenario, settings.tolerance, out.episode.metrics)});
  for (int i = 1; i < request.realisations; ++i) {
    ExecutionDef again = settings.execution;
    again.noise_seed = settings.execution.noise_seed + static_cast<std::uint64_t>(i);
    again.csv_stride_steps = kFirstAndLastRowOnly;
    const EpisodeMetrics m =
        runEpisode(scenario, out.trajectory, again, {}, 1.0 / 30.0, controllerFor(request)).metrics;
    out.realisations.push_back(
        {again.noise_seed, m, judgeEpisode(scenario, settings.tolerance, m)});
  }
  std::vector<RealisationVerdict> verdicts;
  for (const RealisationOutcome& r : out.realisations)
    verdicts.push_back({r.noise_seed, r.verdict});
  out.verdict = judgeRealisations(verdicts, request.min_success_fraction);
}

nlohmann::json metricsOf(const EpisodeRequest& request, const EpisodeOutcome& out,
                         const FrameRecorder* recorder) {
  MetricsDocument doc;
  if (out.driven()) doc.metrics = out.episode.metrics;
  doc.world = request.world->scenario.source_path;
  doc.scenario = request.world->scenario.name;
  doc.tolerance = out.tolerance;
  doc.status = toString(out.verdict.status);
  doc.met = out.verdict.met();
  doc.failure = out.verdict.reason;
  doc.plan_summary = out.plan_summary;
  if (recorder != nullptr) doc.gl_description = recorder->glDescription();
  if (request.components) doc.plugins = pluginsProvenance(*request.components);
  for (const RealisationOutcome& r : out.realisations) {
    doc.realisations.push_back(
        {r.noise_seed, r.metrics, toString(r.verdict.status), r.verdict.met()});
  }
  return metricsDocumentJson(doc);
}

bool keepsFiles(const EpisodeRequest& request, const Verdict& verdict) {
  if (request.out_dir.empty()) return false;
  switch (request.record.files) {
    case FilesPolicy::kNone: return false;
    case FilesPolicy::kFailures: return !verdict.met();
    case FilesPolicy::kAll: return true;
  }
  return false;
}

// plan.json and the plan when it may be driven (a given plan: trajectory.csv alone), then,
// when driven, the executed record and the sensors record (with a pose sensor), and
// metrics.json for a request that drives (its verdict alone when nothing was driven).
void writeFiles(const EpisodeRequest& request, EpisodeOutcome& out) {
  const Scenario& scenario = request.world->scenario;
  const std::string& dir = request.out_dir;
  ensureDirectory(dir);
  if (!request.given_plan) {
    const bool drivable = out.plan && out.plan->solved();
    writePlanFiles(dir, scenario, drivable ? &out.plan->trajectory : nullptr, out.plan_summary);
    if (drivable) out.files.push_back("trajectory.csv");
    out.files.push_back("plan.json");
  } else {
    writeTrajectoryCsv(dir + "/trajectory.csv", out.trajectory, scenario.robot);
    out.files.push_back("trajectory.csv");
  }
  writeEpisodeReport(dir, out);
  if (out.driven()) {
    const RecordFormat format = request.record.format;
    writeExecutedFile(dir + "/" + executedFileName(format), out.episode.rows,
                      out.execution.realism.active(), format,
                      request.world->scenario.robot.isCar());
    out.files.push_back(executedFileName(format));
    if (out.execution.realism.pose_sensor.enabled) {
      writeSensorsFile(dir + "/" + sensorsFileName(format), out.episode.pose_samples,
                       out.episode.metrics.time_step_s, format);
      out.files.push_back(sensorsFileName(format));
    }
  }
  if (!out.metrics.empty()) {
    writeJsonFile(dir + "/metrics.json", out.metrics);
    out.files.push_back("metrics.json");
  }
}

// The film of a failed episode: the first realisation driven again with the camera on.
RecordingResult filmFailure(const EpisodeRequest& request, const EpisodeOutcome& out) {
  const std::unique_ptr<FrameRecorder> recorder = makeRecorder(request, out.trajectory);
  ExecutionDef execution = out.execution;
  execution.csv_stride_steps = kFirstAndLastRowOnly;
  (void)drive(request, out.trajectory, execution, recorder.get());
  return finishFilm(request, *recorder);
}

void drawFigures(const EpisodeRequest& request, EpisodeOutcome& out) {
  const Scenario& scenario = request.world->scenario;
  FigureInputs inputs;
  inputs.steering = steeringExample(scenario);
  if (out.plan) {
    inputs.plans.push_back(planFigure(scenario, out.plan_setup, *out.plan));
  } else {
    inputs.plans.push_back(
        {"file", "plan from " + request.given_plan_source, out.trajectory, {}, {}});
  }
  if (out.driven()) inputs.tracking = trackingSeries(out.episode.rows);
  const std::string dir = request.out_dir + "/figures";
  for (const std::string& path : writeFigures(scenario, inputs, request.figures, dir)) {
    out.files.push_back(path.substr(request.out_dir.size() + 1));
  }
}

// The film's files, as paths under the request's directory.
void addFilmFiles(const EpisodeRequest& request, EpisodeOutcome& out) {
  if (!out.recording) return;
  out.files.push_back("frames");
  for (const VideoOutcome* v : {&out.recording->video, &out.recording->gif}) {
    if (v->status == VideoStatus::kWritten && v->path.size() > request.out_dir.size()) {
      out.files.push_back(v->path.substr(request.out_dir.size() + 1));
    }
  }
}

std::string outDirNeeded(const EpisodeRequest& request) {
  if (request.film.when != FilmWhen::kNever) return "filming";
  if (!request.figures.figures.empty()) return "figures";
  return {};
}

}  // namespace

EpisodeOutcome userCodeFailureOutcome(const EpisodeRequest& request, const UserCodeError& error) {
  const EpisodeSettings settings = resolveSettings(request);
  EpisodeOutcome out;
  out.world = request.world;
  out.plan_setup = settings.plan;
  out.tolerance = settings.tolerance;
  out.verdict = userCodeVerdict(error);
  if (request.given_plan) {
    out.trajectory = *request.given_plan;
    out.plan_summary = trajectorySummary(request.world->scenario, out.trajectory);
    if (!request.given_plan_source.empty()) out.plan_summary["source"] = request.given_plan_source;
  } else if (error.component() == UserCodeError::Component::kPlanner) {
    out.plan_summary = plannerFailureSummary(request, out);
  }
  if (request.drive) out.metrics = metricsOf(request, out, nullptr);
  return out;
}

int EpisodeOutcome::realisationsMet() const {
  int met = 0;
  for (const RealisationOutcome& r : realisations) met += r.verdict.met() ? 1 : 0;
  return met;
}

EpisodeOutcome runEpisodePipeline(const EpisodeRequest& request) {
  checkEpisodeRequest(request);
  if (const std::string what = outDirNeeded(request); !what.empty() && request.out_dir.empty()) {
    throw Error("episode request: " + what + " needs an output directory");
  }
  const EpisodeSettings settings = resolveSettings(request);
  EpisodeOutcome out;
  out.world = request.world;
  out.plan_setup = settings.plan;
  out.tolerance = settings.tolerance;
  planStage(request, out);
  if (!out.verdict.met() || !request.drive) {
    // A request to drive gets its metrics.json whatever stopped it: the verdict, what planned.
    if (request.drive) out.metrics = metricsOf(request, out, nullptr);
    if (keepsFiles(request, out.verdict)) writeFiles(request, out);
    return out;
  }
  const Scenario& scenario = request.world->scenario;
  checkEpisodeLimits(scenario, out.trajectory, settings.execution);
  const bool film_now = request.film.when == FilmWhen::kAlways;
  if (request.film.when != FilmWhen::kNever) {
    checkFrameLimits(request.film.frames,
                     out.trajectory.duration() + settings.execution.max_stop_time_s);
  }
  std::unique_lock<std::mutex> film_lock;
  if (film_now && request.film.lock != nullptr) {
    film_lock = std::unique_lock<std::mutex>(*request.film.lock);
  }
  std::unique_ptr<FrameRecorder> recorder;
  if (film_now) recorder = makeRecorder(request, out.trajectory);
  driveStage(request, settings, recorder.get(), out);
  out.metrics = metricsOf(request, out, recorder.get());
  if (keepsFiles(request, out.verdict)) writeFiles(request, out);
  if (recorder) {
    out.recording = finishFilm(request, *recorder);
    recorder.reset();
    film_lock = {};
  } else if (request.film.when == FilmWhen::kOnFailure && !out.verdict.met()) {
    std::unique_lock<std::mutex> lock;
    if (request.film.lock != nullptr) lock = std::unique_lock<std::mutex>(*request.film.lock);
    out.recording = filmFailure(request, out);
  }
  addFilmFiles(request, out);
  if (!request.figures.figures.empty()) drawFigures(request, out);
  return out;
}

}  // namespace parksim
