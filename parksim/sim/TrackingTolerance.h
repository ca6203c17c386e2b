#pragma once
// The tracking contract as data, for tests and for users' CI: which bounds an episode must meet.
// Defaults are parksim's own acceptance bounds for closed-loop tracking on the study worlds.
//
//   const auto violations = parksim::checkTracking(parksim::TrackingTolerance{}, metrics);
//   EXPECT_TRUE(violations.empty()) << parksim::joinViolations(violations);
//
// or, on a file written by `parksim run`:
//   parksim::checkTrackingFile(parksim::TrackingTolerance{}, "out/metrics.json");

#include <string>
#include <vector>

#include "parksim/sim/Episode.h"

namespace parksim {

struct TrackingTolerance {
  /// Largest position error against the plan at the same time, over the episode, m.
  double max_pos_err_m = 0.005;
  /// Final position error against the scenario's goal, m.
  double goal_pos_err_m = 0.003;
  /// Final heading error against the scenario's goal, degrees.
  double goal_heading_err_deg = 1.5;
  /// Largest number of contact events between the robot and anything but the ground.
  int max_contacts = 0;
  /// Largest horizontal displacement of any parked robot, m.
  double max_parked_displacement_m = 1e-4;
  /// Also require the scenario's own goal tolerance (goal_reached).
  bool require_goal_reached = false;
};

/// Human-readable descriptions of every bound the metrics violate ("max_pos_err_m 0.0061 >
/// 0.005"); empty when all hold.
std::vector<std::string> checkTracking(const TrackingTolerance& tolerance,
                                       const EpisodeMetrics& metrics);

/// The same on a metrics.json file. A file that cannot be read or lacks a key is reported as a
/// violation, not thrown, so a CI script gets one list to print.
std::vector<std::string> checkTrackingFile(const TrackingTolerance& tolerance,
                                           const std::string& metrics_json_path);

/// The violations on one line, separated by "; ".
std::string joinViolations(const std::vector<std::string>& violations);

}  // namespace parksim
