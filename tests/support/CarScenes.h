#pragma once
// Test support: the car scenes the car planner's tests plan on, built in code around the
// mid-size car (RobotDef.h's midSizeCar: 4.689 x 1.942 m, reference point on the rear axle,
// 0.95 m behind it to the rear bumper, 3.739 m ahead of it to the front bumper):
// - parallel: a slot 1.25 car lengths long between two parked cars along a kerb, entered from
//   the street beside them (the slot is shorter than one reverse sweep needs: gear changes);
// - bay_forward / bay_reverse: a free bay in a row of perpendicular bays, head-in and back-in;
// - garage: a closed garage 3.2 m wide, entered head-in through its door from a yard;
// - open_lot: an 80 x 50 m lot with two rows of parked cars, a polygon island and a bollard,
//   the goal in open space far from the start, the way there free.
// Goal tolerances are 0.05 m and 1 degree.

#include <string>
#include <vector>

#include <Eigen/Core>

#include "parksim/core/geometry/Angle.h"
#include "parksim/core/model/Scenario.h"

namespace parksim::testing {

namespace car_scenes {

inline Obstacle box(std::string name, ObstacleKind kind, double cx, double cy, double sx, double sy,
                    double yaw_deg, double height) {
  OrientedBox b;
  b.center = {cx, cy};
  b.half_extents = {0.5 * sx, 0.5 * sy};
  b.yaw = degToRad(yaw_deg);
  return Obstacle::makeBox(std::move(name), kind, b, height);
}

/// A parked mid-size car whose footprint's centre is (cx, cy), heading `yaw_deg`.
inline Obstacle parkedCar(std::string name, double cx, double cy, double yaw_deg) {
  const RobotDef car = midSizeCar();
  return box(std::move(name), ObstacleKind::kParkedRobot, cx, cy, car.length_m, car.width_m,
             yaw_deg, car.height_m);
}

/// A scenario of the mid-size car with the given lot, start and goal (0.05 m, 1 degree).
inline Scenario carScenario(std::string name, const LotBounds& lot, const Pose2& start,
                            const Pose2& goal) {
  Scenario s;
  s.name = std::move(name);
  s.robot = midSizeCar();
  s.lot = lot;
  s.start = start;
  s.goal.pose = goal;
  s.goal.position_tolerance_m = 0.05;
  s.goal.heading_tolerance_rad = degToRad(1.0);
  return s;
}

}  // namespace car_scenes

/// Parallel parking: the slot between x = 15 and x = 15 + 1.25 x 4.689 m, 0.2 m off the kerb.
inline Scenario carParallelScene() {
  using namespace car_scenes;
  const RobotDef car = midSizeCar();
  const double slot = 1.25 * car.length_m;
  const double lane_y = 0.2 + 0.5 * car.width_m;  // parked cars' centre line
  const double rear_overhang = car.length_m - car.front_overhang_m;
  const Pose2 goal{15.0 + 0.5 * (slot - car.length_m) + rear_overhang, lane_y, 0.0};
  Scenario s = carScenario("car_parallel", {0.0, 0.0, 40.0, 9.0}, {4.0, 4.2, 0.0}, goal);
  s.obstacles = {
      box("kerb", ObstacleKind::kCurb, 20.0, -0.25, 40.0, 0.5, 0.0, 0.2),
      box("wall_far", ObstacleKind::kWall, 20.0, 9.75, 40.0, 0.5, 0.0, 1.0),
      parkedCar("car_rear", 15.0 - 0.5 * car.length_m, lane_y, 0.5),
      parkedCar("car_front", 15.0 + slot + 0.5 * car.length_m, lane_y, -0.5),
      parkedCar("car_front2", 15.0 + slot + 1.6 * car.length_m, lane_y, 0.0),
      parkedCar("car_rear2", 15.0 - 1.6 * car.length_m, lane_y, 0.0),
  };
  return s;
}

/// A row of perpendicular bays 2.7 m wide along a back wall at y = 0, every bay but the fifth
/// (x 12.8..15.5) taken, an aisle to y = 12; head-in (`reverse` false) or back-in.
inline Scenario carBayScene(bool reverse) {
  using namespace car_scenes;
  const RobotDef car = midSizeCar();
  const double bay = 2.7;
  const double wall_gap = 0.3;
  const double rear_overhang = car.length_m - car.front_overhang_m;
  // Head-in faces the wall (-90 deg); back-in faces the aisle (+90 deg).
  const Pose2 goal = reverse
                         ? Pose2{2.0 + 4.5 * bay, wall_gap + rear_overhang, degToRad(90)}
                         : Pose2{2.0 + 4.5 * bay, wall_gap + car.front_overhang_m, degToRad(-90)};
  Scenario s = carScenario(reverse ? "car_bay_reverse" : "car_bay_forward", {0.0, 0.0, 30.0, 12.0},
                           {3.0, 8.7, 0.0}, goal);
  s.obstacles = {
      box("back_wall", ObstacleKind::kWall, 15.0, -0.25, 30.0, 0.5, 0.0, 1.0),
      box("far_wall", ObstacleKind::kWall, 15.0, 12.25, 30.0, 0.5, 0.0, 1.0),
  };
  const double offsets[] = {0.1, -0.15, 0.05, 0.12, 0.0, -0.08, 0.15, -0.1, 0.0, 0.1};
  for (int k = 0; k < 10; ++k) {
    if (k == 4) continue;
    s.obstacles.push_back(parkedCar("car_" + std::to_string(k), 2.0 + (k + 0.5) * bay + offsets[k],
                                    wall_gap + 0.5 * car.length_m + 0.1 * (k % 3),
                                    90.0 + offsets[k]));
  }
  return s;
}

/// A garage 3.2 m wide and 6.5 m deep (inside x 10..13.2, y 10..16.5) with its door to the
/// south, entered head-in from a yard; a car parked beside it and a kerb corner as a polygon.
inline Scenario carGarageScene() {
  using namespace car_scenes;
  const RobotDef car = midSizeCar();
  const Pose2 goal{11.6, 16.5 - 0.3 - car.front_overhang_m, degToRad(90)};
  Scenario s = carScenario("car_garage", {0.0, 0.0, 25.0, 16.4}, {2.0, 5.0, 0.0}, goal);
  s.obstacles = {
      box("garage_west", ObstacleKind::kWall, 9.9, 13.35, 0.2, 6.7, 0.0, 2.5),
      box("garage_east", ObstacleKind::kWall, 13.3, 13.35, 0.2, 6.7, 0.0, 2.5),
      box("garage_back", ObstacleKind::kWall, 11.6, 16.6, 3.6, 0.2, 0.0, 2.5),
      box("yard_south", ObstacleKind::kWall, 12.5, -0.25, 25.0, 0.5, 0.0, 1.0),
      parkedCar("car_beside", 6.5, 13.0, 90.0),
      Obstacle::makePolygon("kerb_corner", ObstacleKind::kIsland,
                            {{20.0, 0.0}, {25.0, 0.0}, {25.0, 6.0}, {22.0, 3.0}}, 0.3),
  };
  return s;
}

/// An 80 x 50 m lot with two rows of parked cars, a polygon island and a bollard, all off the
/// way from the south-west (5, 5) to open space at (70, 38), where the car ends heading north
/// (`turn_around`: south, coming round).
inline Scenario carOpenLotScene(bool turn_around = false) {
  using namespace car_scenes;
  Scenario s =
      carScenario(turn_around ? "car_open_lot_turn" : "car_open_lot", {0.0, 0.0, 80.0, 50.0},
                  {5.0, 5.0, 0.0}, {70.0, 38.0, degToRad(turn_around ? -90.0 : 90.0)});
  for (int k = 0; k < 12; ++k) {
    // North-west, facing south; south-east, facing north.
    s.obstacles.push_back(parkedCar("north_" + std::to_string(k), 15.0 + 2.7 * k, 46.0, -90.0));
    if (k % 4 != 1) {
      s.obstacles.push_back(parkedCar("south_" + std::to_string(k), 45.0 + 2.7 * k, 3.0, 90.0));
    }
  }
  s.obstacles.push_back(
      Obstacle::makePolygon("island", ObstacleKind::kIsland,
                            {{15.0, 25.0}, {20.0, 24.0}, {22.0, 28.0}, {16.0, 29.0}}, 0.3));
  s.obstacles.push_back(
      Obstacle::makeCircle("bollard", ObstacleKind::kBollard, {{60.0, 15.0}, 0.3}, 1.0));
  return s;
}

/// Every car scene, by name.
inline std::vector<Scenario> carScenes() {
  return {carParallelScene(), carBayScene(false),     carBayScene(true),
          carGarageScene(),   carOpenLotScene(false), carOpenLotScene(true)};
}

}  // namespace parksim::testing
