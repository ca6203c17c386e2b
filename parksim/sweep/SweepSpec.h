#pragma once
// A sweep: the axes whose product is the set of episodes, what to record per episode and the
// tolerance every episode must meet. Read from a YAML file (format `parksim-sweep/1`,
// docs/sweeps.md) by SweepSpecReader.h.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "parksim/sim/TrackingTolerance.h"
#include "parksim/sweep/EpisodeParams.h"

namespace parksim {

enum class ExecutedCsvPolicy {
  kNone,      ///< no executed.csv (metrics only)
  kFailures,  ///< executed.csv of the episodes that fail their tolerance
  kAll,       ///< executed.csv of every episode
};

const char* toString(ExecutedCsvPolicy policy);

/// What a sweep writes per episode besides its results row, under DIR/episodes/<episode_id>/.
struct RecordDef {
  ExecutedCsvPolicy executed_csv = ExecutedCsvPolicy::kNone;
  /// Rows per second of simulated time in executed.csv (the simulation runs at 240 Hz), Hz.
  double executed_rate_hz = 10.0;
  /// Film the episodes that fail their tolerance: frames/*.png (and episode.mp4 with
  /// film_video). The episode is simulated a second time with the camera on; the simulation is
  /// deterministic, so the film shows the same run.
  bool film_failures = false;
  double film_fps = 15.0;  ///< frames per second of simulated time
  int film_width_px = 640;
  int film_height_px = 480;
  std::string film_view = "top";  ///< top, 3d or both
  bool film_video = false;        ///< also episode.mp4 (needs ffmpeg)
};

/// Bounds of the spec's `tolerance:` section; unset ones keep the world's.
struct ToleranceOverrides {
  std::optional<double> max_pos_err_m;
  std::optional<double> goal_pos_err_m;
  std::optional<double> goal_heading_err_deg;
  std::optional<int> max_contacts;
  std::optional<double> max_parked_displacement_m;

  /// `base` with the set bounds replaced.
  TrackingTolerance appliedTo(TrackingTolerance base) const {
    if (max_pos_err_m) base.max_pos_err_m = *max_pos_err_m;
    if (goal_pos_err_m) base.goal_pos_err_m = *goal_pos_err_m;
    if (goal_heading_err_deg) base.goal_heading_err_deg = *goal_heading_err_deg;
    if (max_contacts) base.max_contacts = *max_contacts;
    if (max_parked_displacement_m) base.max_parked_displacement_m = *max_parked_displacement_m;
    return base;
  }
};

struct SweepSpec {
  std::string source_path;  ///< the spec file, for messages
  std::string name;         ///< sweep name (job names, report titles)
  /// World files as the spec names them (relative to its folder), globs expanded (sorted), in
  /// the spec's order: the results' world_file column.
  std::vector<std::string> world_files;
  /// The same files as paths to open (resolved against the spec file's folder).
  std::vector<std::string> world_paths;
  int worlds_line = 0;  ///< line of `worlds:` in the spec, for errors found when loading them

  // Axes: every combination is one episode. Defaults: one value each (EpisodeParams').
  std::vector<std::string> planners = {"rrt-goal-connect"};
  std::vector<std::string> steerings = {"move-to-pose"};
  std::vector<bool> smoothing = {false};
  std::vector<std::uint64_t> seeds = {1};
  std::vector<int> max_iterations = {2000};
  std::vector<std::string> tracking = {"closed"};
  std::vector<std::string> timing = {"time-optimal"};
  std::vector<std::string> realism = {"world"};
  std::vector<std::uint64_t> noise_seeds = {1};
  std::vector<PoseOffset> start_offsets = {PoseOffset{}};
  std::vector<PoseOffset> goal_offsets = {PoseOffset{}};

  RecordDef record;
  /// Overrides of the tracking tolerance (ToleranceOverrides): an episode meets its tolerance
  /// when its plan is solved, the robot ends within the world's goal tolerance, and the world's
  /// tolerance (its tolerance: section, else parksim's defaults) with these overrides holds.
  ToleranceOverrides tolerance;
};

}  // namespace parksim
