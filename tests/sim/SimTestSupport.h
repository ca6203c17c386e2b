#pragma once
// Scenarios and plans built in code for the simulation tests.

#include <cmath>
#include <string>
#include <vector>

#include "parksim/core/model/DiffDrive.h"
#include "parksim/core/model/Scenario.h"
#include "parksim/core/model/Trajectory.h"

namespace parksim::testing {

/// A lot with no obstacles; the robot starts at `start`.
inline Scenario emptyLot(const Pose2& start = {0.5, 0.5, 0.0}) {
  Scenario s;
  s.name = "empty";
  s.lot = {0.0, 0.0, 2.0, 2.0};
  s.start = start;
  s.goal.pose = start;
  return s;
}

/// Adds a parked robot whose reference point is at `pose` (the ego robot's footprint there).
inline void addParkedRobot(Scenario& s, const std::string& name, const Pose2& pose) {
  Obstacle o;
  o.name = name;
  o.kind = ObstacleKind::kParkedRobot;
  o.box = footprintAt(s.robot, pose);
  o.height_m = s.robot.height_m;
  s.obstacles.push_back(o);
}

inline void addWall(Scenario& s, const std::string& name, double x_min, double y_min, double x_max,
                    double y_max) {
  Obstacle o;
  o.name = name;
  o.kind = ObstacleKind::kWall;
  o.box.center = {0.5 * (x_min + x_max), 0.5 * (y_min + y_max)};
  o.box.half_extents = {0.5 * (x_max - x_min), 0.5 * (y_max - y_min)};
  o.height_m = 0.1;
  s.obstacles.push_back(o);
}

/// A plan made of segments, each holding constant wheel speeds for its duration, in control
/// periods of `period_s`; ends with a zero-speed point.
struct Segment {
  WheelSpeeds wheels;
  double duration_s;
};

inline Trajectory planFromSegments(const Pose2& start, const std::vector<Segment>& segments,
                                   const RobotDef& robot, double period_s = 0.1) {
  Trajectory traj;
  double t = 0.0;
  Pose2 pose = start;
  for (const Segment& seg : segments) {
    const long periods = std::lround(seg.duration_s / period_s);
    for (long i = 0; i < periods; ++i) {
      traj.points.push_back({t, pose, seg.wheels});
      pose = integrateExact(pose, toTwist(seg.wheels, robot), period_s);
      t = static_cast<double>(traj.points.size()) * period_s;
    }
  }
  traj.points.push_back({t, pose, WheelSpeeds{}});
  return traj;
}

/// Ramps wheel speeds from zero to `wheels` and back within the robot's acceleration limit,
/// holding them for `hold_s` in between: a plan the planner could have made.
inline std::vector<Segment> rampedSegments(const WheelSpeeds& wheels, double hold_s,
                                           const RobotDef& robot, double period_s = 0.1) {
  const double top = std::max(std::abs(wheels.left_radps), std::abs(wheels.right_radps));
  const double step = robot.max_wheel_accel_radps2 * period_s;
  const int ramp = static_cast<int>(std::ceil(top / step));
  std::vector<Segment> out;
  for (int i = 1; i <= ramp; ++i) {
    const double f = static_cast<double>(i) / ramp;
    out.push_back({{wheels.left_radps * f, wheels.right_radps * f}, period_s});
  }
  out.push_back({wheels, hold_s});
  for (int i = ramp - 1; i >= 1; --i) {
    const double f = static_cast<double>(i) / ramp;
    out.push_back({{wheels.left_radps * f, wheels.right_radps * f}, period_s});
  }
  return out;
}

}  // namespace parksim::testing
