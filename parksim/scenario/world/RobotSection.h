#pragma once
// A RobotDef as a world file's `robot:` section, and the reader's checks on it: what lets a
// robot built in code (Python's parksim.RobotDef) pass exactly the checks a file's robot does,
// with the same messages, without a second copy of the limits (docs/python.md, "Robots").

#include <string>
#include <vector>

#include "parksim/core/model/RobotDef.h"

namespace parksim {

/// One key of a `robot:` section and its value as YAML text ("car", "2.8").
struct RobotSectionKey {
  std::string key;
  std::string value;
};

/// The section that reads back as `robot` (docs/world-format.md#robot): `drive` and the drive's
/// own keys, numbers written to round-trip; a car's angles in degrees (max_steer_deg,
/// max_steer_rate_degps) and no wheel limits (they follow from the car's own).
std::vector<RobotSectionKey> robotSection(const RobotDef& robot);

/// Throws Error when the world reader would refuse robotSection(robot): every range
/// (PhysicalRanges.h) and every check that joins several keys (the front axle within the body,
/// the wheels within its width, the tightest turn at least half the track, ...). The message
/// is the reader's without a file and line: "robot.axle_distance: must not exceed ...".
void checkRobot(const RobotDef& robot);

}  // namespace parksim
