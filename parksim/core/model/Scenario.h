#pragma once
// The immutable description of one parking problem: lot, obstacles, robot, start and goal,
// and the physical parameters the simulation uses. Loaded once from a world file
// (scenario/world/ScenarioReader.h); everything that changes during an episode lives elsewhere.

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "parksim/core/geometry/Angle.h"
#include "parksim/core/geometry/CompoundShape.h"
#include "parksim/core/geometry/OccupancyGrid.h"
#include "parksim/core/geometry/Pose2.h"
#include "parksim/core/model/Geometry.h"
#include "parksim/core/model/RobotDef.h"

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

/// What an obstacle is. Only kParkedRobot changes behaviour (it has mass and can be pushed);
/// the others differ only in colour and name.
enum class ObstacleKind { kWall, kCurb, kIsland, kBox, kBollard, kPillar, kParkedRobot };

/// The obstacle's ground footprint, extruded vertically from the ground to its height.
enum class ObstacleShape {
  kBox,      ///< `box` is the rectangle
  kCircle,   ///< a disc of `radius_m` around `box.center` (bollards, pillars)
  kPolygon,  ///< `vertices`, convex, counter-clockwise (islands, kerb corners)
  /// `compound`: convex parts (a non-convex polygon, a polygon with holes, a map's cells)
  kCompound,
};

/// An obstacle standing on the ground. Parked robots are boxes with the parked vehicle's
/// footprint.
struct Obstacle {
  std::string name;                           ///< unique within the scenario, e.g. "wall_1"
  ObstacleKind kind = ObstacleKind::kBox;     ///< what it is; parked robots have mass
  ObstacleShape shape = ObstacleShape::kBox;  ///< which of the fields below is the footprint
  /// kBox: the footprint in the lot frame. kCircle, kPolygon and kCompound: the axis-aligned
  /// bounding rectangle (centre = the disc's centre for circles), for code that only needs
  /// extents.
  OrientedBox box;
  double radius_m = 0.0;                  ///< kCircle: radius, m
  std::vector<Eigen::Vector2d> vertices;  ///< kPolygon: lot frame, m, counter-clockwise
  /// kCompound: the convex parts and the outline, shared between copies.
  std::shared_ptr<const CompoundShape> compound;
  double height_m = 0.1;  ///< m
  /// Parked robots: mass, kg; unset means PhysicsDef::parked_robot_mass_kg.
  std::optional<double> mass_kg;

  /// A box obstacle.
  static Obstacle makeBox(std::string name, ObstacleKind kind, const OrientedBox& box,
                          double height_m);
  /// A round obstacle.
  static Obstacle makeCircle(std::string name, ObstacleKind kind, const Circle& circle,
                             double height_m);
  /// A convex polygon obstacle; `vertices` counter-clockwise (isStrictlyConvexCcw).
  static Obstacle makePolygon(std::string name, ObstacleKind kind,
                              std::vector<Eigen::Vector2d> vertices, double height_m);
  /// An obstacle of convex parts (CompoundShape.h).
  static Obstacle makeCompound(std::string name, ObstacleKind kind,
                               std::shared_ptr<const CompoundShape> compound, double height_m);

  Circle circle() const { return {box.center, radius_m}; }
};

/// Signed separation of a footprint box from an obstacle, exact in double for boxes and
/// polygons along the best separating axis and exact for circles: positive when apart (for
/// boxes and polygons a lower bound of the gap), negative when overlapping, 0 when touching.
double separation(const OrientedBox& footprint, const Obstacle& obstacle);

/// Exact planar distance from a footprint box to an obstacle, m (0 when touching or
/// overlapping).
double distance(const OrientedBox& footprint, const Obstacle& obstacle);

/// The obstacle's outline, counter-clockwise, m: the corners of a box or a polygon, and for a
/// circle a regular polygon of `circle_segments` vertices on it (for drawing only). A compound
/// obstacle has no single outline: its bounding rectangle (draw its convexPieces).
std::vector<Eigen::Vector2d> outline(const Obstacle& obstacle, int circle_segments = 48);

/// The obstacle as convex polygons, counter-clockwise, m: its outline for a box, a circle or a
/// convex polygon, its parts for a compound obstacle (for drawing and C-space slices).
std::vector<std::vector<Eigen::Vector2d>> convexPieces(const Obstacle& obstacle,
                                                       int circle_segments = 48);

/// Obstacles no higher than the robot's ground clearance pass under its chassis: the planner
/// ignores them and the simulated chassis does not touch them (the wheels touch the ground only).
bool blocksRobot(const Obstacle& obstacle, const RobotDef& robot);

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

/// Heading error of `theta` from the goal's heading, rad in [0, pi]: against the nearer of the
/// two headings when either is accepted. The episode's verdict and the RL task's reward and
/// success both use it.
double goalHeadingError(const GoalRegion& goal, double theta);

/// Physical parameters for the dynamics world. Defaults are documented here and may be
/// overridden under `physics:` in the world file.
struct PhysicsDef {
  double time_step_s = 1.0 / 240.0;    ///< fixed simulation step, s
  int solver_iterations = 15;          ///< most constraint solver iterations per step
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

/// The planner's motion-check resolution for the study's robot, m: no footprint point moves
/// more than this between two checked poses (MotionValidator.h).
inline constexpr double kStudyMotionCheckResolution_m = 0.001;

/// The motion-check resolution for `robot`: the study's, times the robot's size in study robots
/// (RobotDef::sizeScale), so every robot's checks are as fine, and its plans keep the same
/// clearance, relative to its size: 1 mm for the study's 85 mm robot, 50 mm for a 4.25 m car.
double motionCheckResolution(const RobotDef& robot);

/// Start and goal must keep this clearance from every obstacle and from the lot edge: half the
/// planner's motion-check resolution, the margin by which it grows the footprint at every
/// checked pose. A pose closer than that could never be left or reached by a checked motion.
/// The study's robot's margin; placementMargin(robot) is any robot's.
inline constexpr double kPlacementMargin_m = 0.5 * kStudyMotionCheckResolution_m;

/// Half motionCheckResolution(robot): 0.5 mm for the study's robot.
double placementMargin(const RobotDef& robot);

/// Rounding the placement check forgives: a bumper computed 1e-17 m inside the margin passes.
constexpr double kPlacementTolerance_m = 1e-9;

struct Scenario;

/// The one rule for start and goal poses, applied by the world reader and by the planner
/// alike: the reference point lies at least `margin_m` (unset: placementMargin of the
/// scenario's robot) inside the lot bounds, and the footprint grown by `margin_m` overlaps no
/// obstacle that blocks the robot (see blocksRobot), both up to kPlacementTolerance_m. Returns
/// what is wrong (naming the margin and the obstacle), or nothing when the pose is fine.
std::optional<std::string> placementProblem(const Scenario& scenario, const Pose2& pose,
                                            std::optional<double> margin_m = std::nullopt);

/// placementProblem for the goal: with `either_heading` the goal is fine when either heading
/// is; the message is that of the goal pose as written.
std::optional<std::string> goalPlacementProblem(const Scenario& scenario,
                                                std::optional<double> margin_m = std::nullopt);

/// A map a world's `map:` section brought in, kept so that figures can draw it under the lot.
struct MapLayer {
  std::string name;    ///< the map's obstacle name (its parts' prefix for drawings)
  std::string source;  ///< the map file (relative to the working folder, as it was read)
  /// 16 hex digits of the FNV-1a hash of the map's files (a ROS map's YAML and image): folded
  /// into the world's content hash, so that an edited map is noticed.
  std::string content_hash;
  /// Grid maps (ROS, Moving AI): the cells as the map says them; null for drawings (SVG).
  std::shared_ptr<const OccupancyGrid> grid;
  /// The grid's occupied and unknown cells (as the map says them, before the world's choices
  /// such as inflation) merged into rectangles (GridRectangles.h), for drawing.
  std::shared_ptr<const std::vector<CellRect>> occupied_cells;
  std::shared_ptr<const std::vector<CellRect>> unknown_cells;
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
  /// The maps the obstacles came from, in the world's `map:` order (none for a hand-written lot).
  std::vector<MapLayer> maps;
};

const char* toString(ObstacleKind kind);

}  // namespace parksim
