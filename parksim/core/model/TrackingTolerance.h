#pragma once
// The tracking contract as data: which bounds an episode must meet to pass. A world file's
// tolerance: section sets it (scenario/RealismReader.h), a sweep spec's tolerance: section and
// the command line override it, and the one verdict (pipeline/Verdict.h) judges by it.
// Defaults are parksim's own acceptance bounds for closed-loop tracking on the study worlds;
// defaultTolerance gives them to a robot of any size.

#include "parksim/core/model/RobotDef.h"

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

/// parksim's default tolerance for `robot`, the one a world without a `tolerance:` section (or
/// with some of its bounds) is held to: TrackingTolerance{}'s lengths (max_pos_err_m,
/// goal_pos_err_m, max_parked_displacement_m) times robot.sizeScale(), its heading and
/// contact bounds as they are. The study's robot keeps exactly the numbers above (its scale is
/// 1 to the bit); a 4.25 m robot, 50 study robots long, may stray 250 mm from its plan and end
/// 150 mm from its goal, as the study's robot its 5 mm and 3 mm (docs/simulation.md).
inline TrackingTolerance defaultTolerance(const RobotDef& robot) {
  TrackingTolerance t;
  const double scale = robot.sizeScale();
  t.max_pos_err_m *= scale;
  t.goal_pos_err_m *= scale;
  t.max_parked_displacement_m *= scale;
  return t;
}

}  // namespace parksim
