#include "parksim/scenario/world/ScenarioReader.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>
#include <system_error>
#include <vector>

#include "parksim/core/geometry/Angle.h"
#include "parksim/core/geometry/ConvexPartition.h"
#include "parksim/core/geometry/PolygonRegion.h"
#include "parksim/core/io/Error.h"
#include "parksim/core/io/Text.h"
#include "parksim/core/model/Geometry.h"
#include "parksim/scenario/world/MapSection.h"
#include "parksim/scenario/world/PhysicalRanges.h"
#include "parksim/scenario/world/RealismSections.h"
#include "parksim/scenario/world/RobotReader.h"
#include "parksim/scenario/world/WorldDocument.h"
#include "parksim/scenario/yaml/YamlField.h"

namespace parksim {

namespace {

constexpr std::string_view kFormat = "parksim-world/1";

// Built in place: `"\"" + std::string(s)` and even reserve + append trip GCC 12's false
// -Wrestrict at -O3 (GCC bug 105329).
std::string inQuotes(std::string_view s) {
  std::string out(s.size() + 2, '"');
  s.copy(out.data() + 1, s.size());
  return out;
}

// Angles a pose may carry, degrees: ten turns either way. Larger values are typos or
// overflow, and trigonometry of huge angles loses all precision.
constexpr double kMaxYawDeg = 3600.0;
// Coordinates and lengths, m: far beyond any lot, small enough that squares stay finite and
// millimetres stay resolvable in double.
constexpr double kMaxCoordinate_m = 10000.0;
constexpr double kMaxLength_m = 10000.0;
// Vertices of a polygon's outline or of one hole (all together at most
// kMaxPolygonRegionVertices).
constexpr std::size_t kMaxPolygonVertices = 10000;

double coordinate(const YamlField& f) { return f.inRange(-kMaxCoordinate_m, kMaxCoordinate_m); }

double length(const YamlField& f) {
  const double v = f.positive();
  if (v > kMaxLength_m) {
    f.fail("must be positive and at most " + formatNumber(kMaxLength_m) + " m, got " +
           f.node().Scalar());
  }
  return v;
}

// A list-form yaw is in degrees, but [x, y, 1.5708] is what radians out of ROS habit look
// like. Small fractional values are refused: below one turn in radians (|yaw| < 2 pi), a yaw
// must be a whole number of degrees in the list form; the map form says its unit.
double listYawDeg(const YamlField& f) {
  const double v = f.inRange(-kMaxYawDeg, kMaxYawDeg, " degrees");
  if (std::abs(v) < 2.0 * kPi && v != std::round(v)) {
    f.fail("the list form's angle is in degrees, and " + f.node().Scalar() +
           " looks like radians; write whole degrees (" + formatNumber(std::round(radToDeg(v))) +
           " if that was radians), or the map form {x: .., y: .., yaw_deg: ..} or "
           "{x: .., y: .., yaw_rad: ..}");
  }
  return v;
}

Pose2 readPose(const YamlField& field) {
  if (field.node().IsMap()) {
    const YamlMap m = field.map({"x", "y", "yaw_deg", "yaw_rad"});
    Pose2 pose;
    pose.x = coordinate(m.required("x"));
    pose.y = coordinate(m.required("y"));
    const std::optional<YamlField> deg = m.optional("yaw_deg");
    const std::optional<YamlField> rad = m.optional("yaw_rad");
    if (deg && rad) rad->fail("give the heading once: yaw_deg or yaw_rad, not both");
    if (!deg && !rad) {
      YamlField(field.node(), field.path() + ".yaw_deg", field.line(), field.source())
          .fail("missing required field (or yaw_rad)");
    }
    pose.theta = deg ? degToRad(deg->inRange(-kMaxYawDeg, kMaxYawDeg, " degrees"))
                     : rad->inRange(-degToRad(kMaxYawDeg), degToRad(kMaxYawDeg), " rad");
    return pose;
  }
  if (!field.node().IsSequence() || field.node().size() != 3) {
    field.fail("must be a list [x, y, yaw_deg] of 3 numbers or a map {x, y, yaw_deg}, got " +
               field.describeValue());
  }
  const std::vector<YamlField> items = field.items();
  return {coordinate(items[0]), coordinate(items[1]), degToRad(listYawDeg(items[2]))};
}

void readFormat(const YamlField& field) {
  // Checked before the other keys so that a file of another version reports its version,
  // not the first key this reader does not know.
  const std::string format = field.text();
  if (format != kFormat) field.fail("expected " + inQuotes(kFormat) + ", got " + inQuotes(format));
}

LotBounds readLot(const YamlField& field) {
  const YamlMap m = field.map({"x_min", "y_min", "x_max", "y_max"});
  LotBounds lot;
  lot.x_min_m = coordinate(m.required("x_min"));
  lot.y_min_m = coordinate(m.required("y_min"));
  const YamlField x_max = m.required("x_max");
  const YamlField y_max = m.required("y_max");
  lot.x_max_m = coordinate(x_max);
  lot.y_max_m = coordinate(y_max);
  if (!(lot.x_max_m > lot.x_min_m)) {
    x_max.fail("must be greater than lot.x_min (" + formatNumber(lot.x_min_m) + "), got " +
               x_max.node().Scalar());
  }
  if (!(lot.y_max_m > lot.y_min_m)) {
    y_max.fail("must be greater than lot.y_min (" + formatNumber(lot.y_min_m) + "), got " +
               y_max.node().Scalar());
  }
  return lot;
}

PhysicsDef readPhysics(const YamlField& field) {
  const YamlMap m =
      field.map({"time_step_s", "solver_iterations", "gravity_mps2", "chassis_mass_kg",
                 "wheel_mass_kg", "wheel_friction", "support_friction", "ground_friction",
                 "max_wheel_torque_nm", "parked_robot_mass_kg", "obstacle_friction"});
  PhysicsDef physics;
  const auto positive = [&m](std::string_view key, double& out) {
    if (const std::optional<YamlField> f = m.optional(key)) {
      out = rangedValue(*f, "physics." + std::string(key));
    }
  };
  // A friction coefficient of zero is a frictionless contact, which the slider wants.
  const auto friction = [&m](std::string_view key, double& out) {
    if (const std::optional<YamlField> f = m.optional(key)) {
      out = rangedValue(*f, "physics." + std::string(key), true);
    }
  };
  positive("time_step_s", physics.time_step_s);
  if (const std::optional<YamlField> f = m.optional("solver_iterations")) {
    physics.solver_iterations = f->positiveInt();
    if (const std::optional<std::string> problem =
            rangeProblem(physicalRange("physics.solver_iterations"), physics.solver_iterations,
                         f->node().Scalar())) {
      f->fail(*problem);
    }
  }
  positive("gravity_mps2", physics.gravity_mps2);
  positive("chassis_mass_kg", physics.chassis_mass_kg);
  positive("wheel_mass_kg", physics.wheel_mass_kg);
  friction("wheel_friction", physics.wheel_friction);
  friction("support_friction", physics.support_friction);
  friction("ground_friction", physics.ground_friction);
  positive("max_wheel_torque_nm", physics.max_wheel_torque_nm);
  positive("parked_robot_mass_kg", physics.parked_robot_mass_kg);
  friction("obstacle_friction", physics.obstacle_friction);
  return physics;
}

}  // namespace

ObstacleKind readObstacleKind(const YamlField& field) {
  const std::string kind = field.text();
  if (kind == "wall") return ObstacleKind::kWall;
  if (kind == "curb") return ObstacleKind::kCurb;
  if (kind == "island") return ObstacleKind::kIsland;
  if (kind == "box") return ObstacleKind::kBox;
  if (kind == "bollard") return ObstacleKind::kBollard;
  if (kind == "pillar") return ObstacleKind::kPillar;
  if (kind == "parked_robot") {
    field.fail("parked robots are listed under parked_robots, with a pose instead of a size");
  }
  field.fail("unknown kind " + inQuotes(kind) +
             "; expected one of: wall, curb, island, box, bollard, pillar");
}

namespace {

Eigen::Vector2d readPoint(const YamlField& field) {
  field.numbers(2, "[x, y]");
  const std::vector<YamlField> xy = field.items();
  return {coordinate(xy[0]), coordinate(xy[1])};
}

// One ring of [x, y] points.
std::vector<Eigen::Vector2d> readRing(const YamlField& field) {
  const std::vector<YamlField> items = field.listUpTo(kMaxPolygonVertices);
  if (items.size() < 3) {
    field.fail("a polygon needs at least 3 vertices [x, y], got " + std::to_string(items.size()));
  }
  std::vector<Eigen::Vector2d> ring;
  for (const YamlField& item : items) ring.push_back(readPoint(item));
  return ring;
}

// Any simple polygon, with holes: vertices in either winding. A convex one without holes is
// stored as it is (counter-clockwise); any other is cut into convex parts exactly
// (ConvexPartition.h), because the exact queries and Bullet's shapes are convex.
Obstacle readPolygon(const Obstacle& base, const YamlField& vertices,
                     const std::optional<YamlField>& holes_field) {
  PolygonWithHoles region;
  region.outer = readRing(vertices);
  if (holes_field) {
    for (const YamlField& hole : holes_field->listUpTo(kMaxPolygonVertices)) {
      region.holes.push_back(readRing(hole));
    }
  }
  if (region.holes.empty()) {
    std::vector<Eigen::Vector2d> ccw = region.outer;
    if (signedDoubleArea(ccw) < 0.0) std::reverse(ccw.begin(), ccw.end());
    if (isStrictlyConvexCcw(ccw)) {
      return Obstacle::makePolygon(base.name, base.kind, std::move(ccw), base.height_m);
    }
  }
  if (const std::optional<std::string> problem = regionProblem(region)) {
    (holes_field && problem->rfind("hole", 0) == 0 ? *holes_field : vertices)
        .fail("must be a simple polygon (holes inside it, apart): " + *problem);
  }
  const PolygonWithHoles tidy = normalizedRegion(region);
  std::vector<std::vector<Eigen::Vector2d>> rings{tidy.outer};
  rings.insert(rings.end(), tidy.holes.begin(), tidy.holes.end());
  return Obstacle::makeCompound(base.name, base.kind,
                                CompoundShape::make(convexPartition(region), std::move(rings)),
                                base.height_m);
}

Obstacle readObstacle(const YamlField& field) {
  const YamlMap m = field.map(
      {"name", "kind", "center", "size", "yaw_deg", "radius", "vertices", "holes", "height"});
  Obstacle obstacle;
  obstacle.name = m.required("name").name();
  obstacle.kind = readObstacleKind(m.required("kind"));
  const std::optional<YamlField> size = m.optional("size");
  const std::optional<YamlField> radius = m.optional("radius");
  const std::optional<YamlField> vertices = m.optional("vertices");
  const int shapes = int(size.has_value()) + int(radius.has_value()) + int(vertices.has_value());
  if (shapes != 1) {
    const YamlField at = shapes == 0 ? m.required("kind") : *(vertices ? vertices : radius);
    YamlField(at.node(), field.path(), at.line(), field.source())
        .fail("give exactly one shape: size (a box), radius (a circle) or vertices (a polygon)");
  }
  if (const std::optional<YamlField> holes = m.optional("holes"); holes && !vertices) {
    holes->fail("holes belong to a polygon (vertices)");
  }
  if (vertices) {
    for (const char* key : {"center", "yaw_deg"}) {
      if (const std::optional<YamlField> f = m.optional(key)) {
        f->fail("a polygon is placed by its vertices alone");
      }
    }
    obstacle = readPolygon(obstacle, *vertices, m.optional("holes"));
  } else if (radius) {
    if (const std::optional<YamlField> f = m.optional("yaw_deg")) {
      f->fail("a circle has no heading");
    }
    const Eigen::Vector2d center = readPoint(m.required("center"));
    obstacle = Obstacle::makeCircle(obstacle.name, obstacle.kind, {center, length(*radius)},
                                    obstacle.height_m);
  } else {
    const Eigen::Vector2d center = readPoint(m.required("center"));
    size->numbers(2, "[sx, sy]");
    const std::vector<YamlField> sides = size->items();
    obstacle.box.center = center;
    obstacle.box.half_extents = {0.5 * length(sides[0]), 0.5 * length(sides[1])};
    if (const std::optional<YamlField> f = m.optional("yaw_deg")) {
      obstacle.box.yaw = degToRad(f->inRange(-kMaxYawDeg, kMaxYawDeg, " degrees"));
    }
  }
  if (const std::optional<YamlField> f = m.optional("height")) obstacle.height_m = length(*f);
  return obstacle;
}

// A parked vehicle is the ego robot's footprint unless it gives its own size; its mass
// defaults to physics.parked_robot_mass_kg.
Obstacle readParkedRobot(const YamlField& field, const RobotDef& robot) {
  const YamlMap m =
      field.map({"name", "pose", "height", "length", "width", "front_overhang", "mass_kg"});
  Obstacle obstacle;
  obstacle.name = m.required("name").name();
  obstacle.kind = ObstacleKind::kParkedRobot;
  RobotDef body = robot;
  const std::optional<YamlField> len = m.optional("length");
  const std::optional<YamlField> overhang = m.optional("front_overhang");
  if (len) {
    body.length_m = length(*len);
    // Without its own overhang, a longer vehicle keeps the ego's overhang ratio.
    if (!overhang) body.front_overhang_m = robot.front_overhang_m / robot.length_m * body.length_m;
  }
  if (const std::optional<YamlField> f = m.optional("width")) body.width_m = length(*f);
  if (overhang) {
    body.front_overhang_m = overhang->nonNegative();
    if (body.front_overhang_m > body.length_m) {
      overhang->fail("must not exceed the vehicle's length (" + formatNumber(body.length_m) +
                     "), got " + overhang->node().Scalar());
    }
  }
  obstacle.box = footprintAt(body, readPose(m.required("pose")));
  obstacle.height_m = robot.height_m;
  if (const std::optional<YamlField> f = m.optional("height")) obstacle.height_m = length(*f);
  if (const std::optional<YamlField> f = m.optional("mass_kg")) {
    obstacle.mass_kg = rangedValue(*f, "parked_robots.mass_kg");
  }
  return obstacle;
}

GoalRegion readGoal(const YamlField& field) {
  const YamlMap m =
      field.map({"pose", "position_tolerance", "heading_tolerance_deg", "either_heading"});
  GoalRegion goal;
  goal.pose = readPose(m.required("pose"));
  if (const std::optional<YamlField> f = m.optional("position_tolerance")) {
    goal.position_tolerance_m = f->positive();
  }
  if (const std::optional<YamlField> f = m.optional("heading_tolerance_deg")) {
    goal.heading_tolerance_rad = degToRad(f->positive());
  }
  if (const std::optional<YamlField> f = m.optional("either_heading")) {
    goal.either_heading = f->boolean();
  }
  return goal;
}

// A start or goal the robot cannot stand on makes every episode fail for a reason that has
// nothing to do with the planner; catch it where the file can say which entry is wrong. The
// rule is core's placementProblem, the planner's own.
void checkPlacement(const YamlField& field, const std::optional<std::string>& problem) {
  if (problem) field.fail(*problem);
}

// Names identify obstacles in messages, logs and figures, so they must be unique across
// both lists. Remembers where each was first used.
class NameRegistry {
 public:
  void add(const YamlField& entry, const std::string& name) {
    const auto [it, inserted] = first_line_.emplace(name, entry.line());
    if (!inserted) {
      entry.fail("duplicate name " + inQuotes(name) + " (already used at line " +
                 std::to_string(it->second) + ")");
    }
  }

 private:
  std::map<std::string, int> first_line_;
};

std::string readWholeFile(const std::string& path) {
  // Type and size first: a FIFO, a device (/dev/zero, /dev/urandom) or a huge file would
  // otherwise be read until memory runs out.
  std::error_code ec;
  const std::filesystem::file_status status = std::filesystem::status(path, ec);
  if (ec) throw Error(escapeText(path + ": cannot open: " + ec.message()));
  if (std::filesystem::is_directory(status)) {
    throw Error(escapeText(path + ": cannot open: is a directory"));
  }
  if (!std::filesystem::is_regular_file(status)) {
    throw Error(escapeText(path + ": cannot open: not a regular file"));
  }
  const std::uintmax_t size = std::filesystem::file_size(path, ec);
  if (!ec && size > kMaxWorldFileBytes) {
    throw Error(escapeText(path + ": file size: " + std::to_string(size) +
                           " bytes; a world file may hold at most " +
                           std::to_string(kMaxWorldFileBytes) + " bytes (1 MiB)"));
  }
  errno = 0;
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    const int err = errno;
    throw Error(escapeText(
        path + ": cannot open: " +
        (err != 0 ? std::generic_category().message(err) : std::string("unknown error"))));
  }
  // Read at most one byte past the limit, in case the file grew since it was measured.
  std::string text(kMaxWorldFileBytes + 1, '\0');
  in.read(text.data(), static_cast<std::streamsize>(text.size()));
  if (in.bad()) throw Error(escapeText(path + ": cannot read: input error"));
  text.resize(static_cast<std::size_t>(in.gcount()));
  if (text.size() > kMaxWorldFileBytes) {
    throw Error(escapeText(path + ": file size: a world file may hold at most " +
                           std::to_string(kMaxWorldFileBytes) + " bytes (1 MiB)"));
  }
  return text;
}

}  // namespace

YAML::Node loadWorldDocument(std::string_view yaml_text, const std::string& source_name) {
  if (yaml_text.size() > kMaxWorldFileBytes) {
    throw Error(escapeText(source_name + ": file size: " + std::to_string(yaml_text.size()) +
                           " bytes; a world file may hold at most " +
                           std::to_string(kMaxWorldFileBytes) + " bytes (1 MiB)"));
  }
  const YAML::Node document =
      loadSingleYamlDocument(std::string(yaml_text), source_name, "world file", kFormat);
  if (document.IsNull()) {
    YamlField(document, "", 1, source_name)
        .fail("empty; a world file is a map that starts with format: " + std::string(kFormat));
  }
  return document;
}

World readWorldDocument(const YAML::Node& document, const std::string& source_name) {
  const YamlField root(document, "", 1, source_name);
  const YamlMap top(root);
  readFormat(top.required("format"));
  top.rejectUnknownKeys({"format", "name", "lot", "map", "robot", "obstacles", "parked_robots",
                         "start", "goal", "physics", "realism", "tolerance"});
  World world;
  Scenario& s = world.scenario;
  s.source_path = source_name;
  s.name = top.required("name").name();
  // Maps first: without `lot:` their extent is the lot.
  NameRegistry names;
  std::optional<MapSection> maps;
  if (const std::optional<YamlField> list = top.optional("map")) {
    maps = readMapSection(*list, source_name);
    s.maps = std::move(maps->layers);
    world.warnings = std::move(maps->warnings);
  }
  if (top.optional("lot") || !maps || maps->extent.isEmpty()) {
    s.lot = readLot(top.required("lot"));
  } else {
    s.lot = {maps->extent.min().x(), maps->extent.min().y(), maps->extent.max().x(),
             maps->extent.max().y()};
  }
  // The robot comes before the parked robots whatever the key order: they share its footprint.
  const std::optional<YamlField> robot = top.optional("robot");
  const std::optional<YamlField> physics = top.optional("physics");
  if (robot) s.robot = readRobot(*robot);
  if (physics) s.physics = readPhysics(*physics);
  // Values each within range may still ask more of the wheels than they can give; the robot's
  // section is named (its shape and limits are what a user changes), else the physics one.
  if (const std::optional<std::string> problem = driveProblem(s.robot, s.physics)) {
    (robot ? *robot : physics ? *physics : root).fail(*problem);
  }
  // The default tolerance follows the robot's size.
  world.sections = readRealismSections(top, s.robot, s.physics);

  if (maps) {
    const YamlField list = *top.optional("map");
    for (Obstacle& o : maps->obstacles) {
      names.add(list, o.name);
      s.obstacles.push_back(std::move(o));
    }
  }
  if (const std::optional<YamlField> list = top.optional("obstacles")) {
    for (const YamlField& entry : list->listUpTo(kMaxObstacles)) {
      s.obstacles.push_back(readObstacle(entry));
      names.add(YamlMap(entry).required("name"), s.obstacles.back().name);
    }
  }
  if (const std::optional<YamlField> list = top.optional("parked_robots")) {
    for (const YamlField& entry : list->listUpTo(kMaxParkedRobots)) {
      s.obstacles.push_back(readParkedRobot(entry, s.robot));
      names.add(YamlMap(entry).required("name"), s.obstacles.back().name);
    }
  }

  const YamlField start = top.required("start");
  s.start = readPose(start);
  const YamlField goal = top.required("goal");
  s.goal = readGoal(goal);
  checkPlacement(start, placementProblem(s, s.start));
  checkPlacement(YamlMap(goal).required("pose"), goalPlacementProblem(s));
  return world;
}

std::string readWorldFile(const std::string& path) { return readWholeFile(path); }

Pose2 parsePose(std::string_view text, const std::string& what) {
  YAML::Node node;
  try {
    // "x,y,deg" as a command line writes it is a list without brackets.
    const std::string_view trimmed =
        text.substr(std::min(text.find_first_not_of(" \t"), text.size()));
    const bool bare = !trimmed.empty() && trimmed.front() != '[' && trimmed.front() != '{';
    // Built in place, as inQuotes: "[" + std::string(text) trips GCC 12's false -Wrestrict.
    std::string yaml(text.size() + (bare ? 2 : 0), '[');
    text.copy(yaml.data() + (bare ? 1 : 0), text.size());
    if (bare) yaml.back() = ']';
    node = YAML::Load(yaml);
  } catch (const YAML::Exception& e) {
    throw Error(
        escapeText(what + ": cannot read a pose from \"" + std::string(text) + "\": " + e.msg));
  }
  return readPose(YamlField(node, what, 0, ""));
}

}  // namespace parksim
