#pragma once
// A sweep: the axes whose product is the set of episodes, what to record per episode and the
// tolerance every episode must meet. Read from a YAML file (format `parksim-sweep/1`,
// docs/sweeps.md) by SweepSpecReader.h.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "parksim/scenario/ScenarioOverrides.h"

#include "parksim/pipeline/EpisodeRequest.h"
#include "parksim/sweep/EpisodeParams.h"

namespace parksim {

/// What a sweep writes per episode besides its results row, under DIR/episodes/<episode_id>/.
struct SweepRecordDef {
  /// Which episodes keep their files (trajectory.csv, plan.json, executed.csv, metrics.json).
  FilesPolicy executed_csv = FilesPolicy::kNone;
  /// Rows per second of simulated time in executed.csv (the simulation runs at 240 Hz), Hz.
  double executed_rate_hz = 10.0;
  /// How the records are stored: executed.npz and sensors.npz (NumPy archives: exact, a third of
  /// the CSV's bytes or less) by default, or executed.csv and sensors.csv.
  RecordFormat format = RecordFormat::kNpz;
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

struct SweepSpec {
  std::string source_path;  ///< the spec file, for messages
  std::string name;         ///< sweep name (job names, report titles)
  /// World files as the spec names them (relative to its folder), globs expanded (sorted), in
  /// the spec's order: the results' world_file column.
  std::vector<std::string> world_files;
  /// The same files as paths to open (resolved against the spec file's folder).
  std::vector<std::string> world_paths;
  int worlds_line = 0;  ///< line of `worlds:` in the spec, for errors found when loading them
  /// `set:` axes: a world field (a path as `--set` takes it, e.g. "map[0].inflation") and its
  /// values (YAML text). Every combination of them makes a variant of every world, named
  /// "<name>{<path>=<value>,...}" (so its episodes have ids of their own).
  std::vector<std::pair<std::string, std::vector<std::string>>> set_axes;
  /// Per entry of world_paths: its variant's overrides (all empty without `set:`; with it,
  /// world_files and world_paths list each file once per variant).
  std::vector<std::vector<ScenarioOverride>> world_overrides;

  // Axes: every combination is one episode. Defaults: one value each, the library's
  // (EpisodeParams{}, which takes them from PlanSetup{} and EpisodeRequest{}).
  std::vector<std::string> planners = {EpisodeParams{}.planner};
  std::vector<std::string> steerings = {EpisodeParams{}.steering};
  std::vector<bool> smoothing = {EpisodeParams{}.smooth};
  std::vector<std::uint64_t> seeds = {EpisodeParams{}.seed};
  /// kAutoIterations ("auto" in a spec): the lot's budget.
  std::vector<int> max_iterations = {EpisodeParams{}.max_iterations};
  std::vector<std::string> tracking = {EpisodeParams{}.tracking};
  std::vector<std::string> timing = {EpisodeParams{}.timing};
  std::vector<std::string> realism = {EpisodeParams{}.realism};
  std::vector<std::uint64_t> noise_seeds = {EpisodeParams{}.noise_seed};
  std::vector<PoseOffset> start_offsets = {PoseOffset{}};
  std::vector<PoseOffset> goal_offsets = {PoseOffset{}};
  /// Lines of the offsets in the spec (0: not from a file), for errors found with the worlds.
  std::vector<int> start_offset_lines = {0};
  std::vector<int> goal_offset_lines = {0};

  SweepRecordDef record;
  /// Overrides of the tracking tolerance (ToleranceOverrides): an episode meets its tolerance
  /// when its plan is solved, the robot ends within the world's goal tolerance, and the world's
  /// tolerance (its tolerance: section, else parksim's defaults) with these overrides holds.
  ToleranceOverrides tolerance;
};

}  // namespace parksim
