#pragma once
// One episode of a sweep as plain parameters, its canonical text and its stable id.
//
// The id is a hash of the canonical text, never the episode's position in the sweep, so the
// same episode has the same id in every sweep that contains it, however the spec lists or
// orders its axes, and whichever shard or machine runs it: a baseline table and a candidate
// table of the same spec pair by id. The canonical text spells every parameter, defaults
// included, after the id format's version ("ids=2;world=...;planner=..."), so an id never
// depends on what the defaults were when it was made; a change of the parameters an id spells
// is a new format version, and a table of another version is refused by name
// (docs/sweeps.md, "Episode ids").

#include <cstdint>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "parksim/core/Fnv1a.h"
#include "parksim/pipeline/EpisodeRequest.h"
#include "parksim/planner/PlanScenario.h"
#include "parksim/sim/ExecutionDef.h"

namespace parksim {

/// A rigid offset of a pose in the lot frame: translation, then rotation about the new point.
struct PoseOffset {
  double dx_m = 0.0;      ///< m
  double dy_m = 0.0;      ///< m
  double dyaw_deg = 0.0;  ///< degrees, counter-clockwise

  bool isZero() const { return dx_m == 0.0 && dy_m == 0.0 && dyaw_deg == 0.0; }
  friend bool operator==(const PoseOffset&, const PoseOffset&) = default;
};

/// The version of the canonical text the ids hash (sweep.json records it).
inline constexpr int kEpisodeIdFormat = 2;

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
  /// How the plan is timed ("time-optimal", "study").
  std::string timing = toString(PlanSetup{}.timing);
  /// The robot's realism: "world" (the world file's realism: section; ideal without one) or a
  /// preset name ("ideal", "lab", "odometry").
  std::string realism = kDefaultRealism;
  /// Seeds the realism's random draws (as `parksim run`).
  std::uint64_t noise_seed = kDefaultNoiseSeed;
  PoseOffset start_offset;  ///< applied to the world's start
  PoseOffset goal_offset;   ///< applied to the world's goal pose

  friend bool operator==(const EpisodeParams&, const EpisodeParams&) = default;
};

/// "ids=2;world=...;planner=...;...": every parameter but world_file, keys in a fixed order,
/// numbers in their shortest round-trip form, an automatic budget as "auto".
std::string canonicalString(const EpisodeParams& params);

/// fnv1a64(canonicalString(params)) as 16 lower-case hex digits.
std::string episodeId(const EpisodeParams& params);

/// Every parameter as the leading columns of a results row, after episode_id (max_iterations
/// 0 when automatic; the budget used is the row's plan_max_iterations): world, world_file, planner,
/// steering, smooth, seed, max_iterations, tracking, timing, realism, noise_seed, start_dx_m,
/// start_dy_m, start_dyaw_deg, goal_dx_m, goal_dy_m, goal_dyaw_deg.
void appendParamColumns(const EpisodeParams& params, nlohmann::ordered_json& row);

}  // namespace parksim
