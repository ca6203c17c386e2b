#pragma once
// The immutable description of one parking problem: lot, obstacles, robot, start and goal,
// and the physical parameters the simulation uses. Loaded once from a world file
// (scenario/ScenarioReader.h); everything that changes during an episode lives elsewhere.

#include <string>
#include <vector>

#include "parksim/core/Angle.h"
#include "parksim/core/Geometry.h"
#include "parksim/core/Pose2.h"
#include "parksim/core/RobotDef.h"

namespace parksim {

/// Axis-aligned bounds of the lot. They bound the reference point: the planner samples inside
/// them and the start and goal must lie inside them. They are not walls (the study's lot has
/// none); walls are obstacles.
struct LotBounds {
  double x_min_m = 0.0;
  double y_min_m = 0.0;
  double x_max_m = 1.8;
  double y_max_m = 1.2;

  bool contains(double x, double y) const {
    return x >= x_min_m && x <= x_max_m && y >= y_min_m && y <= y_max_m;
  }
};

enum class ObstacleKind { kWall, kCurb, kIsland, kBox, kParkedRobot };

/// A box standing on the ground. Parked robots are boxes with the parked robot's footprint.
struct Obstacle {
  std::string name;                        ///< unique within the scenario, e.g. "wall_1"
  ObstacleKind kind = ObstacleKind::kBox;  ///< what it is; parked robots have mass
  OrientedBox box;                         ///< footprint in the lot frame
  double height_m = 0.1;                   ///< m
};

/// Where the robot must end.
struct GoalRegion {
  Pose2 pose;
  /// Largest accepted distance of the reference point from the goal position, m.
  double position_tolerance_m = 0.001;
  /// Largest accepted heading error, rad.
  double heading_tolerance_rad = degToRad(0.5);
  /// Accept the goal heading plus pi as well (head-in or back-in).
  bool either_heading = false;
};

/// Physical parameters for the dynamics world. Defaults are documented here and may be
/// overridden under `physics:` in the world file.
struct PhysicsDef {
  double time_step_s = 1.0 / 240.0;    ///< fixed simulation step, s
  int solver_iterations = 50;          ///< constraint solver iterations per step
  double gravity_mps2 = 9.81;          ///< m/s^2, pointing down
  double chassis_mass_kg = 0.20;       ///< ego chassis mass, kg
  double wheel_mass_kg = 0.02;         ///< each driven wheel, kg
  double wheel_friction = 1.0;         ///< Coulomb friction coefficient of the wheels
  double support_friction = 0.0;       ///< passive support (slider) friction coefficient
  double ground_friction = 1.0;        ///< ground friction coefficient
  double max_wheel_torque_nm = 0.2;    ///< motor torque limit per wheel, N m
  double parked_robot_mass_kg = 0.25;  ///< each parked robot, kg (dynamic, can be pushed)
  double obstacle_friction = 0.5;      ///< walls, islands and parked robots
};

struct Scenario {
  std::string name;         ///< from the file, e.g. "head_in"
  std::string source_path;  ///< file it was read from, for messages
  LotBounds lot;
  std::vector<Obstacle> obstacles;
  RobotDef robot;
  Pose2 start;
  GoalRegion goal;
  PhysicsDef physics;
};

const char* toString(ObstacleKind kind);

}  // namespace parksim
