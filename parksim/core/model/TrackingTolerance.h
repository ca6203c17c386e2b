#pragma once
// The tracking contract as data: which bounds an episode must meet to pass. A world file's
// tolerance: section sets it (scenario/world/RealismReader.h), a sweep spec's tolerance: section
// and the command line override it, and the one verdict (pipeline/Verdict.h) judges by it. Defaults
// are parksim's own acceptance bounds for closed-loop tracking on the study worlds.

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
  /// Also require the scenario's own goal tolerance (goal_reached). The verdict always does;
  /// this makes checkTracking's list of violations say so too.
  bool require_goal_reached = false;
};

}  // namespace parksim
