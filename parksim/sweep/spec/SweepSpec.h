#pragma once
// A sweep: the axes whose product is the set of episodes (parksim's own knobs, and `set:` axes
// over any value a world file or a planner or controller takes, on a grid or sampled), what to
// record per episode and the tolerance every episode must meet. Read from a YAML file (format
// `parksim-sweep/1`, docs/sweeps.md) by SweepSpecReader.h.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "parksim/scenario/world/ScenarioOverrides.h"

#include "parksim/pipeline/EpisodeRequest.h"
#include "parksim/sweep/spec/EpisodeParams.h"

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

/// A distribution a `set:` value is drawn from, once per sample (SetValues.h has the
/// generator).
struct SetDistribution {
  enum class Kind {
    kUniform,  ///< {uniform: [a, b]}: a + (b - a) u, u uniform in [0, 1)
    kNormal,   ///< {normal: [mean, sd]}
    kChoice,   ///< {choice: [v1, v2, ...]}: each with the same chance
  };
  Kind kind = Kind::kUniform;
  double a = 0.0;  ///< uniform: the low end; normal: the mean
  double b = 0.0;  ///< uniform: the high end; normal: the standard deviation (> 0)
  std::vector<std::string> choices;  ///< kChoice: the values, as canonical text
};

/// One `set:` axis: a path a `--set PATH=VALUE` can name (a world value: robot, physics,
/// realism, tolerance, goal, obstacles, ...), or `planner.NAME` / `controller.NAME`, a parameter
/// of the selected planner or controller; with a list of values (a grid) or a distribution
/// (drawn `samples:` times).
struct SetAxis {
  std::string path;
  /// The grid's values as canonical text (numbers in their shortest round-trip form, booleans
  /// true/false, lists and maps as compact JSON, other text as written); empty for a
  /// distribution.
  std::vector<std::string> values;
  std::optional<SetDistribution> distribution;
  int line = 0;  ///< of the path in the spec, for errors found with the worlds

  enum class Target { kWorld, kPlanner, kController };
  /// What the path sets: planner. and controller. paths are the selected implementation's
  /// parameters (EpisodeParams::planner_params, controller_params), the others world values.
  Target target() const;
  /// The parameter's name for kPlanner and kController ("planner.step_m": "step_m").
  std::string parameterName() const;
};

/// `samples:`: how many times the spec's distributions are drawn, and the seed of the draws.
struct SampleDef {
  std::uint64_t count = 0;
  std::uint64_t seed = 0;
};

/// One entry of the planners or controllers axis.
struct ComponentChoice {
  std::string name;  ///< the registered name ("command" for `{command: [...]}`)
  ParamMap params;   ///< its fixed parameters (ParamMap.h)
  int line = 0;      ///< its line in the spec, for errors found when the spec expands
  std::string path;  ///< where in the spec ("planners[1]"), likewise

  friend bool operator==(const ComponentChoice&, const ComponentChoice&) = default;
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
  /// `plugins:`: shared libraries whose planners and controllers the axes may name
  /// (usercode/PluginLoader.h), as the spec names them and resolved against its folder.
  std::vector<std::string> plugin_files;
  std::vector<std::string> plugin_paths;
  int plugins_line = 0;

  // Axes: every combination is one episode. Defaults: one value each, the library's
  // (EpisodeParams{}, which takes them from PlanSetup{} and EpisodeRequest{}).
  /// `planners:` and `controllers:`: each entry a registered name with its own fixed
  /// parameters (a command's, or `params:`), which the set: axes' planner.NAME and
  /// controller.NAME join.
  std::vector<ComponentChoice> planners = {{EpisodeParams{}.planner, {}, 0, ""}};
  std::vector<ComponentChoice> controllers = {{EpisodeParams{}.controller, {}, 0, ""}};
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

  /// `set:` axes, sorted by path. Grid values multiply the episodes like the axes above; with
  /// distributions, `samples` draws each of them `count` times (sample 0, 1, ...), and every
  /// draw is one more combination.
  std::vector<SetAxis> set;
  std::optional<SampleDef> samples;
  int samples_line = 0;

  SweepRecordDef record;
  /// Overrides of the tracking tolerance (ToleranceOverrides): an episode meets its tolerance
  /// when its plan is solved, the robot ends within the world's goal tolerance, and the world's
  /// tolerance (its tolerance: section, else parksim's defaults) with these overrides holds.
  ToleranceOverrides tolerance;
};

}  // namespace parksim
