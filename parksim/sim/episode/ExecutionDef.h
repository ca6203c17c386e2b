#pragma once
// How an episode drives a plan: open loop (exactly the planned wheel speeds) or closed loop
// (a controller's commands, Controller.h), and when the episode ends.

#include <cstdint>
#include <string>

#include "parksim/realism/RealismDef.h"

namespace parksim {

enum class TrackingMode {
  kOpen,  ///< the planned wheel speeds, held for each control period; no correction
  /// the controller's commands (Controller.h; by default the tracking controller: planned wheel
  /// speeds as feed-forward plus Kanayama feedback on the pose error)
  kClosed,
};

const char* toString(TrackingMode mode);
/// Parses "open" or "closed"; throws Error otherwise.
TrackingMode trackingModeFromString(const std::string& name);

/// ExecutionDef's default tracking, named for the options and parameters that state it.
inline constexpr TrackingMode kDefaultTracking = TrackingMode::kClosed;

struct ExecutionDef {
  TrackingMode tracking = kDefaultTracking;
  /// After the plan ends the robot is commanded to stop (open: zero wheel speeds; closed: hold
  /// the plan's last pose, zero feed-forward). It is at rest once its reference point moves
  /// slower than this, m/s ...
  double rest_speed_mps = 2e-4;
  /// ... and it turns slower than this, rad/s ...
  double rest_yaw_rate_radps = 2e-3;
  /// ... for this long without a break, s. The episode then ends.
  double rest_hold_s = 0.25;
  /// The episode ends at the latest this long after the plan's end, at rest or not, s.
  double max_stop_time_s = 5.0;
  /// A body touching the chassis again within this time of its last touch continues the same
  /// contact event (contact points flicker while the robot pushes something), s.
  double contact_merge_s = 0.1;
  /// executed.csv gets one row every this many simulation steps (1: every step).
  int csv_stride_steps = 1;
  /// Most physics steps one episode may take: the plan's duration plus max_stop_time_s, in
  /// time steps of the scenario's physics (docs/limits.md). 10^6 steps are ~69 min of
  /// simulated time at 240 Hz, ~1 min of CPU and ~100 MB of executed rows at csv stride 1.
  double max_steps = 1e6;
  /// Motors, calibration, sensors, estimation and control-loop timing (realism/RealismDef.h);
  /// the default is the `ideal` robot.
  RealismDef realism;
  /// Seed of every random draw of the realism layers (calibration errors, motor gains, sensor
  /// noise), independent of the planner's seed. Each layer draws from its own generator
  /// seeded by (noise_seed, layer), so switching one layer off leaves the others' draws.
  std::uint64_t noise_seed = 0;
};

}  // namespace parksim
