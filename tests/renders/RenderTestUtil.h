#pragma once
// Shared by the render tests: a small lot built in code and per-test output directories.

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "parksim/core/geometry/Angle.h"
#include "parksim/core/model/Geometry.h"
#include "parksim/core/model/Scenario.h"
#include "parksim/renders/scene/SceneBuilder.h"
#include "tests/support/TestPaths.h"

namespace parksim::rendertest {

inline Obstacle box(std::string name, ObstacleKind kind, double cx, double cy, double sx, double sy,
                    double yaw_deg = 0.0, double height = 0.1) {
  Obstacle o;
  o.name = std::move(name);
  o.kind = kind;
  o.box.center = {cx, cy};
  o.box.half_extents = {0.5 * sx, 0.5 * sy};
  o.box.yaw = degToRad(yaw_deg);
  o.height_m = height;
  return o;
}

/// A drive in progress: the robot at the driven path's end, its reference pose, the paths and
/// an overlay. The spans point at `planned` and `executed`, which must outlive the view.
inline ViewState drivingView(const std::vector<Pose2>& planned, const std::vector<Pose2>& executed,
                             const Pose2& reference, const Overlay& overlay) {
  ViewState view;
  view.robot = executed.back();
  view.reference = reference;
  view.planned_path = planned;
  view.executed_path = executed;
  view.overlay = overlay;
  return view;
}

/// The study's lot in outline: a wall with a gap, an island, two parked robots.
inline Scenario testLot() {
  Scenario s;
  s.name = "test_lot";
  s.obstacles = {
      box("wall_1", ObstacleKind::kWall, 0.55, 1.0, 0.1, 0.4),
      box("wall_2", ObstacleKind::kWall, 0.55, 0.2, 0.1, 0.4),
      box("island", ObstacleKind::kIsland, 1.2, 0.65, 0.8, 0.1),
  };
  Obstacle parked;
  parked.name = "robot_5";
  parked.kind = ObstacleKind::kParkedRobot;
  parked.box = footprintAt(s.robot, {1.3425, 0.01, degToRad(-90.0)});
  parked.height_m = s.robot.height_m;
  s.obstacles.push_back(parked);
  s.start = {0.1, 0.1, degToRad(90.0)};
  s.goal.pose = {1.5, 0.04, degToRad(-90.0)};
  return s;
}

/// A fresh, empty directory for one test's files, under the build tree.
inline std::string outputDir(const std::string& name) {
  const std::string dir = parksim::testing::binaryDir() + "/test-output/renders/" + name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

}  // namespace parksim::rendertest

#include <vector>

#include "parksim/core/model/DiffDrive.h"
#include "parksim/core/model/Trajectory.h"

namespace parksim::rendertest {

/// A trajectory from `start` holding each twist for `period_s`, integrated exactly.
inline Trajectory drive(const RobotDef& robot, Pose2 start, const std::vector<Twist>& twists,
                        double period_s = 0.1) {
  Trajectory traj;
  double t = 0.0;
  Pose2 pose = start;
  for (const Twist& tw : twists) {
    traj.points.push_back({t, pose, toWheelSpeeds(tw, robot)});
    pose = integrateExact(pose, tw, period_s);
    t += period_s;
  }
  traj.points.push_back({t, pose, {}});
  return traj;
}

/// Straight north from the start, then a left arc.
inline Trajectory sampleDrive(const RobotDef& robot, Pose2 start) {
  std::vector<Twist> twists(20, Twist{0.1, 0.0});
  twists.insert(twists.end(), 20, Twist{0.1, 0.6});
  return drive(robot, start, twists);
}

}  // namespace parksim::rendertest
