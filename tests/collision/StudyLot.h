#pragma once
// The study's parking lot built in code (/work/shared/reference/README.md, rows 1-11), for the
// collision tests and bench/bench_collision.cpp. Parked robots are the ego footprint at a
// pose, as the world files describe them; their rectangles equal the table's.

#include <string>
#include <utility>

#include "core/Angle.h"
#include "core/Geometry.h"
#include "core/Scenario.h"

namespace parksim::testlot {

/// Rectangle from its lower-left corner and size, as the study's table gives them.
inline OrientedBox cornerBox(double x, double y, double width, double height) {
  OrientedBox box;
  box.center = {x + 0.5 * width, y + 0.5 * height};
  box.half_extents = {0.5 * width, 0.5 * height};
  return box;
}

inline Obstacle makeObstacle(std::string name, ObstacleKind kind, const OrientedBox& box,
                             double height_m) {
  Obstacle obstacle;
  obstacle.name = std::move(name);
  obstacle.kind = kind;
  obstacle.box = box;
  obstacle.height_m = height_m;
  return obstacle;
}

inline Scenario studyLot() {
  Scenario s;
  s.name = "study_lot";
  const RobotDef& robot = s.robot;
  const double wall_h = 0.1;
  auto parked = [&](int row, double x, double y, double heading_deg) {
    return makeObstacle("robot_" + std::to_string(row), ObstacleKind::kParkedRobot,
                        footprintAt(robot, {x, y, degToRad(heading_deg)}), robot.height_m);
  };
  s.obstacles = {
      makeObstacle("wall_1", ObstacleKind::kWall, cornerBox(0.5, 0.8, 0.1, 0.4), wall_h),
      makeObstacle("wall_2", ObstacleKind::kWall, cornerBox(0.5, 0.0, 0.1, 0.4), wall_h),
      parked(3, 0.7425, 0.01, -90),
      parked(4, 1.0425, 0.01, -90),
      parked(5, 1.3425, 0.01, -90),
      parked(6, 1.6425, 0.01, -90),
      makeObstacle("island_7", ObstacleKind::kIsland, cornerBox(0.8, 0.6, 0.8, 0.1), wall_h),
      parked(8, 0.77, 1.1575, 0),
      parked(9, 1.07, 1.1575, 0),
      parked(10, 1.37, 1.1575, 0),
      parked(11, 1.67, 1.1575, 0),
  };
  s.start = {0.1, 0.1, degToRad(90)};
  return s;
}

}  // namespace parksim::testlot
