#pragma once
// One episode of a sweep as plain parameters, its canonical text and its stable id.
//
// The id is a hash of the canonical text, never the episode's position in the sweep, so the
// same episode has the same id in every sweep that contains it, however the spec lists or
// orders its axes, and whichever shard or machine runs it: a baseline table and a candidate
// table of the same spec pair by id. The canonical text spells every parameter of the
// format's core, defaults included, after the id format's version ("ids=3;world=...;
// planner=..."), so an id never depends on what the defaults were when it was made; a change
// of what the core spells is a new format version, and a table of another version is refused
// by name (docs/sweeps.md, "Episode ids").
//
// Keys after the core (the sample, set: values, planner and controller parameters) are spelled
// only when they differ from the value the format fixes for them (absent, empty): adding such a
// key (the controller's name, fixed at "tracking") leaves every existing id as it is, so it
// needs no new format version. kExtensionKeys lists them.

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "parksim/core/io/Fnv1a.h"
#include "parksim/core/params/ParamMap.h"
#include "parksim/pipeline/EpisodeRequest.h"
#include "parksim/planner/base/PlanScenario.h"
#include "parksim/sim/episode/ExecutionDef.h"

namespace parksim {

/// A rigid offset of a pose in the lot frame: translation, then rotation about the new point.
struct PoseOffset {
  double dx_m = 0.0;      ///< m
  double dy_m = 0.0;      ///< m
  double dyaw_deg = 0.0;  ///< degrees, counter-clockwise

  bool isZero() const { return dx_m == 0.0 && dy_m == 0.0 && dyaw_deg == 0.0; }
  friend bool operator==(const PoseOffset&, const PoseOffset&) = default;
};

/// The version of the canonical text the ids hash (sweep.json records it). 3: the extension
/// keys (kExtensionKeys) after the core of format 2.
inline constexpr int kEpisodeIdFormat = 3;

/// Defaults are the library's, the same as `parksim run` and Python's (PlanSetup{},
/// EpisodeRequest{}, ExecutionDef{}).
struct EpisodeParams {
  std::string world;       ///< the world's Scenario::name (its file is provenance, not identity)
  std::string world_file;  ///< the file the world was read from; not part of the id
  std::string planner = PlanSetup{}.planner;
  std::string steering = toString(PlanSetup{}.steering_kind);
  bool smooth = PlanSetup{}.search.smooth;
  std::uint64_t seed = PlanSetup{}.search.seed;  ///< planner seed
  /// Iteration budget; kAutoIterations ("auto") is the lot's (defaultIterationBudget).
  int max_iterations = PlanSetup{}.search.max_iterations;
  std::string tracking = toString(kDefaultTracking);  ///< "closed" or "open"
  /// The controller of closed-loop tracking, by its registered name (Controller.h). In the
  /// canonical text only when it is not the default (so ids of format 3 made before it stay).
  std::string controller = kDefaultController;
  /// How the plan is timed ("time-optimal", "study").
  std::string timing = toString(PlanSetup{}.timing);
  /// The robot's realism: "world" (the world file's realism: section; ideal without one) or a
  /// preset name ("ideal", "lab", "odometry").
  std::string realism = kDefaultRealism;
  /// Seeds the realism's random draws (as `parksim run`).
  std::uint64_t noise_seed = kDefaultNoiseSeed;
  PoseOffset start_offset;  ///< applied to the world's start
  PoseOffset goal_offset;   ///< applied to the world's goal pose

  // Extension keys: spelled in the canonical text only when set (see the top of this file); the
  // controller above too, when it is not the default.
  /// The draw of a sampled spec (`samples:`), 0, 1, ...; none for a grid.
  std::optional<std::uint64_t> sample;
  /// World values of `set:` axes: path -> canonical value text (SetValues.h), applied to the
  /// world file as `--set PATH=VALUE` applies them. Each is a column named by its path.
  ParamMap world_set;
  /// Parameters of the planner and of the controller (`set:` paths planner.NAME,
  /// controller.NAME): name -> canonical text, passed to the request (PlanSetup::planner_params,
  /// EpisodeRequest::controller_params). Columns planner.NAME, controller.NAME.
  ParamMap planner_params;
  ParamMap controller_params;

  friend bool operator==(const EpisodeParams&, const EpisodeParams&) = default;
};

/// The extension keys of format 3, in the order the canonical text spells them: "sample",
/// "controller" (its name, when not the default), then "set.<path>" per world value,
/// "planner.<name>", "controller.<name>" (each map sorted).
inline constexpr const char* kExtensionKeys[] = {"sample", "controller", "set.", "planner.",
                                                 "controller."};

/// "ids=3;world=...;planner=...;...": every core parameter but world_file, keys in a fixed
/// order, numbers in their shortest round-trip form, an automatic budget as "auto"; then the
/// extension keys that are set (";sample=4;set.robot.max_wheel_speed_radps=6;planner.k=2").
std::string canonicalString(const EpisodeParams& params);

/// fnv1a64(canonicalString(params)) as 16 lower-case hex digits.
std::string episodeId(const EpisodeParams& params);

/// Every parameter as the leading columns of a results row, after episode_id: the episode
/// record's parameter fields (results/EpisodeRecord.h, in its order: world, world_file,
/// planner, ..., goal_dyaw_deg, sample when sampled; max_iterations 0 when automatic, the
/// budget used being the row's plan_max_iterations), then the set columns: each world value
/// by its path, planner.NAME, controller.NAME (values as SetValues.h's setValueJson).
void appendParamColumns(const EpisodeParams& params, nlohmann::ordered_json& row);

/// The set columns of `params` (appendParamColumns' names after the fixed parameters).
std::vector<std::string> setColumnsOf(const EpisodeParams& params);

}  // namespace parksim
