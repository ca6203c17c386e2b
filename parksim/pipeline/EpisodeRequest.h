#pragma once
// A whole episode as data in: which world, how to plan (or which plan to drive), how to drive
// it, how real the robot is, which tolerance it must meet, what to record and film, and where
// to write. `parksim plan`, `parksim run`, `parksim render`, every sweep episode and Python's
// plan(), run() and Episode build one of these and hand it to runEpisodePipeline
// (EpisodePipeline.h).
//
// The defaults here and in the Def structs they hold (PlanSetup, ExecutionDef,
// TrackingTolerance, FrameDef) are parksim's defaults, defined once: a front-end that leaves a
// field alone runs exactly what every other front-end runs.

#include <cstdint>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>

#include "parksim/core/model/TrackingTolerance.h"
#include "parksim/core/model/Trajectory.h"
#include "parksim/core/params/ParamMap.h"
#include "parksim/core/system/UserCodeWatch.h"
#include "parksim/planner/base/PlanScenario.h"
#include "parksim/renders/film/FrameRecorder.h"
#include "parksim/renders/plots/Figures.h"
#include "parksim/results/episode/ExecutedFile.h"
#include "parksim/scenario/world/World.h"
#include "parksim/sim/episode/ExecutionDef.h"
#include "parksim/usercode/Components.h"

namespace parksim {

/// Which episodes write their files (trajectory.csv, plan.json, executed.csv, sensors.csv,
/// metrics.json) into EpisodeRequest::out_dir.
enum class FilesPolicy {
  kNone,      ///< none: the outcome only
  kFailures,  ///< only episodes whose verdict is not met
  kAll,       ///< every episode
};

const char* toString(FilesPolicy policy);
/// Parses "none", "failures" or "all"; throws Error otherwise.
FilesPolicy filesPolicyFromString(const std::string& name);

/// What is kept of an episode.
struct RecordDef {
  FilesPolicy files = FilesPolicy::kAll;
  /// Rows per second of simulated time in executed.csv, Hz; 0 keeps the execution's
  /// csv_stride_steps (1 by default: every physics step, 240 Hz by default). The first and the
  /// last row are always kept.
  double executed_rate_hz = 0.0;
  /// executed.csv and sensors.csv, or executed.npz and sensors.npz (the same columns, exact, a
  /// third of the bytes or less; results/ExecutedFile.h).
  RecordFormat format = RecordFormat::kCsv;
};

/// When the episode is filmed (frames/*.png, and a video if FrameDef asks).
enum class FilmWhen {
  kNever,
  kAlways,     ///< while it is driven
  kOnFailure,  ///< only when the verdict is not met: driven a second time with the camera on
               ///< (the simulation is deterministic, so the film shows the same run)
};

struct FilmDef {
  FilmWhen when = FilmWhen::kNever;
  /// Frame rate, size, view, video; its out_dir is replaced by the request's out_dir.
  FrameDef frames;
  /// Held while filming when set: one off-screen GL context at a time (sweep workers share one).
  std::mutex* lock = nullptr;
};

/// Bounds that replace the world's tolerance (its tolerance: section, or parksim's defaults).
struct ToleranceOverrides {
  std::optional<double> max_pos_err_m;
  std::optional<double> goal_pos_err_m;
  std::optional<double> goal_heading_err_deg;
  std::optional<int> max_contacts;
  std::optional<double> max_parked_displacement_m;

  /// `base` with the set bounds replaced.
  TrackingTolerance appliedTo(TrackingTolerance base) const;
};

/// Progress of the long stages, for a display (the command line's progress line).
struct PipelineProgress {
  /// Planning: (iterations or node expansions done, budget).
  PlanProgress plan;
  /// Filming: (frames written so far, frames expected).
  std::function<void(long, long)> frames;
};

/// The defaults of EpisodeRequest's realism and noise seed, named so that the sweep's parameters
/// and the command line's options state them without building a whole request.
inline constexpr const char* kDefaultRealism = "world";
inline constexpr std::uint64_t kDefaultNoiseSeed = 1;

/// A FigureDef that draws nothing (an EpisodeRequest's default).
inline FigureDef noFigures() {
  FigureDef def;
  def.figures = FigureSelection{};
  return def;
}

struct EpisodeRequest {
  /// The world (loadWorld). Required.
  std::shared_ptr<const World> world;

  /// How to plan. Its defaults are parksim's: time-a-star with smoothing, time-optimal
  /// timing (PlanScenario.h).
  PlanSetup plan;
  /// Drive this plan instead of planning (a plan file, a Python array). It must start at the
  /// world's start (within 1 mm and 0.5 deg).
  std::optional<Trajectory> given_plan;
  /// Where given_plan came from, for messages and metrics.json ("plan_source").
  std::string given_plan_source;

  /// The planners and controllers plan.planner and `controller` are looked up in: parksim's own
  /// and the plugins a front-end loaded (usercode/Components.h). Null: parksim's own.
  std::shared_ptr<const Components> components;
  /// The controller that drives the plan in closed-loop tracking, by its registered name (a
  /// built-in or a plugin's), and its parameters (ParamMap.h).
  std::string controller = kDefaultController;
  ParamMap controller_params;

  /// false: plan only (`parksim plan`, `parksim render`); the verdict is met when solved.
  bool drive = true;
  /// Tracking mode, controller gains, when the episode ends. Its realism and noise_seed are
  /// set from `realism` and `noise_seed` below.
  ExecutionDef execution;
  /// "world": the world file's realism: section, the ideal robot without one; or a preset name
  /// (realismPresetNames(): "ideal", "lab", "odometry").
  std::string realism = kDefaultRealism;
  /// Seed of the realism's random draws (calibration, motor gains, sensor noise); independent
  /// of the planner's seed.
  std::uint64_t noise_seed = kDefaultNoiseSeed;
  /// Drive the plan this many times, under noise seeds noise_seed, noise_seed + 1, ...; files
  /// and film are of the first.
  int realisations = 1;
  /// With several realisations: the share that must meet the tolerance for a met verdict.
  double min_success_fraction = 1.0;
  /// Replaces bounds of the world's tolerance.
  ToleranceOverrides tolerance;

  /// Files and rows kept.
  RecordDef record;
  FilmDef film;
  /// Figures drawn into out_dir/figures/ (lot map, steering, C-space, plan, tracking error);
  /// none by default.
  FigureDef figures = noFigures();

  /// Time limits on user code (docs/limits.md): a user's planner per plan, a user's controller
  /// per command. The process watching a worker (UserCodeIsolation.h; IsolatedEpisode.h)
  /// enforces them on code in parksim's process; the command planner and controller stop their
  /// program at them (or at their own timeout parameters, whichever is shorter). Code in the
  /// caller's process without a watch is not stopped.
  UserCodeLimits limits;
  /// Set in a process that runs user code under a watch (UserCodeIsolation.h): the episode
  /// says there when it enters and leaves a user's planner or controller. Not owned.
  UserCodeWatch* watch = nullptr;

  /// Directory the files go to (created when needed); empty: nothing is written.
  std::string out_dir;
  PipelineProgress progress;
};

}  // namespace parksim
