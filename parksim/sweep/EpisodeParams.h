#pragma once
// One episode of a sweep as plain parameters, its canonical text and its stable id.
//
// The id is a hash of the canonical text, never the episode's position in the sweep, so the
// same episode has the same id in every sweep that contains it, however the spec lists or
// orders its axes, and whichever shard or machine runs it. A parameter at its default value is
// left out of the canonical text: adding a new axis (with a default that reproduces today's
// behaviour) keeps every existing id.

#include <cstdint>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

namespace parksim {

/// A rigid offset of a pose in the lot frame: translation, then rotation about the new point.
struct PoseOffset {
  double dx_m = 0.0;      ///< m
  double dy_m = 0.0;      ///< m
  double dyaw_deg = 0.0;  ///< degrees, counter-clockwise

  bool isZero() const { return dx_m == 0.0 && dy_m == 0.0 && dyaw_deg == 0.0; }
  friend bool operator==(const PoseOffset&, const PoseOffset&) = default;
};

/// Defaults here are the sweep format's, frozen: they define which values the canonical text
/// omits, so changing one would change ids.
struct EpisodeParams {
  std::string world;       ///< the world's Scenario::name (its file is provenance, not identity)
  std::string world_file;  ///< the file the world was read from; not part of the id
  std::string planner = "rrt-goal-connect";
  std::string steering = "move-to-pose";
  bool smooth = false;
  std::uint64_t seed = 1;  ///< planner seed
  int max_iterations = 2000;
  std::string tracking = "closed";      ///< "closed" or "open"
  std::string timing = "time-optimal";  ///< how the plan is timed ("time-optimal", "study")
  /// The robot's realism: "world" (the world file's realism: section; ideal without one) or a
  /// preset name ("ideal", "lab", "odometry").
  std::string realism = "world";
  std::uint64_t noise_seed = 1;  ///< seeds the realism's random draws (as `parksim run`)
  PoseOffset start_offset;       ///< applied to the world's start
  PoseOffset goal_offset;        ///< applied to the world's goal pose

  friend bool operator==(const EpisodeParams&, const EpisodeParams&) = default;
};

/// "key=value;key=value" over the parameters that differ from the defaults, world, planner
/// and seed always; keys in a fixed order, numbers in their shortest round-trip form.
std::string canonicalString(const EpisodeParams& params);

/// 64-bit FNV-1a of `text`.
std::uint64_t fnv1a64(std::string_view text);

/// fnv1a64(canonicalString(params)) as 16 lower-case hex digits.
std::string episodeId(const EpisodeParams& params);

/// Every parameter (defaults included) as the leading columns of a results row, after
/// episode_id: world, world_file, planner, steering, smooth, seed, max_iterations, tracking,
/// timing, realism, noise_seed, start_dx_m, start_dy_m, start_dyaw_deg, goal_dx_m, goal_dy_m,
/// goal_dyaw_deg.
void appendParamColumns(const EpisodeParams& params, nlohmann::ordered_json& row);

}  // namespace parksim
