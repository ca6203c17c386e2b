#include "parksim/scenario/ScenarioReader.h"

#include <cerrno>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>
#include <system_error>
#include <vector>

#include "parksim/core/Angle.h"
#include "parksim/core/Error.h"
#include "parksim/core/Geometry.h"
#include "parksim/scenario/WorldDocument.h"
#include "parksim/scenario/YamlField.h"

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

Pose2 readPose(const YamlField& field) {
  const std::vector<double> v = field.numbers(3, "[x, y, yaw_deg]");
  return {v[0], v[1], degToRad(v[2])};
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
  lot.x_min_m = m.required("x_min").number();
  lot.y_min_m = m.required("y_min").number();
  const YamlField x_max = m.required("x_max");
  const YamlField y_max = m.required("y_max");
  lot.x_max_m = x_max.number();
  lot.y_max_m = y_max.number();
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

RobotDef readRobot(const YamlField& field) {
  const YamlMap m = field.map({"length", "width", "front_overhang", "wheel_base", "wheel_radius",
                               "max_wheel_speed_radps", "max_wheel_accel_radps2", "height"});
  RobotDef robot;
  // Each key overrides one field; absent keys keep the study's robot.
  const auto set = [&m](std::string_view key, double& out) {
    if (const std::optional<YamlField> f = m.optional(key)) out = f->positive();
  };
  set("length", robot.length_m);
  set("width", robot.width_m);
  set("wheel_base", robot.wheel_base_m);
  set("wheel_radius", robot.wheel_radius_m);
  set("max_wheel_speed_radps", robot.max_wheel_speed_radps);
  set("max_wheel_accel_radps2", robot.max_wheel_accel_radps2);
  set("height", robot.height_m);

  // Zero is a real design (axle at the front edge); beyond the length the reference point
  // would lie outside the body it steers.
  const std::optional<YamlField> overhang = m.optional("front_overhang");
  if (overhang) robot.front_overhang_m = overhang->nonNegative();
  if (robot.front_overhang_m > robot.length_m) {
    if (overhang) {
      overhang->fail("must not exceed robot.length (" + formatNumber(robot.length_m) + "), got " +
                     overhang->node().Scalar());
    }
    const YamlField length = m.required("length");
    length.fail("must be at least robot.front_overhang (" + formatNumber(robot.front_overhang_m) +
                "), got " + length.node().Scalar());
  }
  return robot;
}

PhysicsDef readPhysics(const YamlField& field) {
  const YamlMap m =
      field.map({"time_step_s", "solver_iterations", "gravity_mps2", "chassis_mass_kg",
                 "wheel_mass_kg", "wheel_friction", "support_friction", "ground_friction",
                 "max_wheel_torque_nm", "parked_robot_mass_kg", "obstacle_friction"});
  PhysicsDef physics;
  const auto positive = [&m](std::string_view key, double& out) {
    if (const std::optional<YamlField> f = m.optional(key)) out = f->positive();
  };
  // A friction coefficient of zero is a frictionless contact, which the slider wants.
  const auto friction = [&m](std::string_view key, double& out) {
    if (const std::optional<YamlField> f = m.optional(key)) out = f->nonNegative();
  };
  positive("time_step_s", physics.time_step_s);
  if (const std::optional<YamlField> f = m.optional("solver_iterations")) {
    physics.solver_iterations = f->positiveInt();
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

ObstacleKind readKind(const YamlField& field) {
  const std::string kind = field.text();
  if (kind == "wall") return ObstacleKind::kWall;
  if (kind == "curb") return ObstacleKind::kCurb;
  if (kind == "island") return ObstacleKind::kIsland;
  if (kind == "box") return ObstacleKind::kBox;
  if (kind == "parked_robot") {
    field.fail("parked robots are listed under parked_robots, with a pose instead of a size");
  }
  field.fail("unknown kind " + inQuotes(kind) + "; expected one of: wall, curb, island, box");
}

Obstacle readObstacle(const YamlField& field) {
  const YamlMap m = field.map({"name", "kind", "center", "size", "yaw_deg", "height"});
  Obstacle obstacle;
  obstacle.name = m.required("name").text();
  obstacle.kind = readKind(m.required("kind"));
  const std::vector<double> center = m.required("center").numbers(2, "[x, y]");
  const YamlField size = m.required("size");
  size.numbers(2, "[sx, sy]");
  const std::vector<YamlField> sides = size.items();
  obstacle.box.center = {center[0], center[1]};
  obstacle.box.half_extents = {0.5 * sides[0].positive(), 0.5 * sides[1].positive()};
  if (const std::optional<YamlField> f = m.optional("yaw_deg")) {
    obstacle.box.yaw = degToRad(f->number());
  }
  if (const std::optional<YamlField> f = m.optional("height")) obstacle.height_m = f->positive();
  return obstacle;
}

Obstacle readParkedRobot(const YamlField& field, const RobotDef& robot) {
  const YamlMap m = field.map({"name", "pose", "height"});
  Obstacle obstacle;
  obstacle.name = m.required("name").text();
  obstacle.kind = ObstacleKind::kParkedRobot;
  obstacle.box = footprintAt(robot, readPose(m.required("pose")));
  obstacle.height_m = robot.height_m;
  if (const std::optional<YamlField> f = m.optional("height")) obstacle.height_m = f->positive();
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
// nothing to do with the planner; catch it where the file can say which entry is wrong.
void checkPlacement(const YamlField& field, const Pose2& pose, const Scenario& s) {
  if (!s.lot.contains(pose.x, pose.y)) {
    field.fail("reference point (" + formatNumber(pose.x) + ", " + formatNumber(pose.y) +
               ") is outside the lot [" + formatNumber(s.lot.x_min_m) + ", " +
               formatNumber(s.lot.x_max_m) + "] x [" + formatNumber(s.lot.y_min_m) + ", " +
               formatNumber(s.lot.y_max_m) + "]");
  }
  const OrientedBox footprint = footprintAt(s.robot, pose);
  for (const Obstacle& obstacle : s.obstacles) {
    if (boxesOverlap(footprint, obstacle.box)) {
      field.fail("robot footprint overlaps obstacle " + inQuotes(obstacle.name));
    }
  }
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
  // An ifstream opens a directory and then fails inside the read; say so up front.
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) throw Error(path + ": cannot open: is a directory");
  errno = 0;
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    const int err = errno;
    throw Error(path + ": cannot open: " +
                (err != 0 ? std::generic_category().message(err) : std::string("unknown error")));
  }
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw Error(path + ": cannot read: input error");
  return text.str();
}

}  // namespace

Scenario parseScenario(std::string_view yaml_text, const std::string& source_name) {
  return readWorldDocument(loadWorldDocument(yaml_text, source_name), source_name);
}

YAML::Node loadWorldDocument(std::string_view yaml_text, const std::string& source_name) {
  std::vector<YAML::Node> documents;
  try {
    documents = YAML::LoadAll(std::string(yaml_text));
  } catch (const YAML::Exception& e) {
    throw Error(source_name + ":" + std::to_string(lineOf(e.mark)) + ": (syntax): " + e.msg);
  }
  if (documents.empty()) {
    YamlField(YAML::Node(), "", 1, source_name)
        .fail("empty; a world file is a map that starts with format: " + std::string(kFormat));
  }
  if (documents.size() > 1) {
    YamlField(documents[1], "", lineOf(documents[1].Mark()), source_name)
        .fail("a world file holds one YAML document, found " + std::to_string(documents.size()));
  }
  return documents.front();
}

Scenario readWorldDocument(const YAML::Node& document, const std::string& source_name) {
  const YamlField root(document, "", 1, source_name);
  const YamlMap top(root);
  readFormat(top.required("format"));
  top.rejectUnknownKeys(
      {"format", "name", "lot", "robot", "obstacles", "parked_robots", "start", "goal", "physics"});

  Scenario s;
  s.source_path = source_name;
  s.name = top.required("name").text();
  s.lot = readLot(top.required("lot"));
  // The robot comes before the parked robots whatever the key order: they share its footprint.
  if (const std::optional<YamlField> f = top.optional("robot")) s.robot = readRobot(*f);
  if (const std::optional<YamlField> f = top.optional("physics")) s.physics = readPhysics(*f);

  NameRegistry names;
  if (const std::optional<YamlField> list = top.optional("obstacles")) {
    for (const YamlField& entry : list->items()) {
      s.obstacles.push_back(readObstacle(entry));
      names.add(YamlMap(entry).required("name"), s.obstacles.back().name);
    }
  }
  if (const std::optional<YamlField> list = top.optional("parked_robots")) {
    for (const YamlField& entry : list->items()) {
      s.obstacles.push_back(readParkedRobot(entry, s.robot));
      names.add(YamlMap(entry).required("name"), s.obstacles.back().name);
    }
  }

  const YamlField start = top.required("start");
  s.start = readPose(start);
  const YamlField goal = top.required("goal");
  s.goal = readGoal(goal);
  checkPlacement(start, s.start, s);
  checkPlacement(YamlMap(goal).required("pose"), s.goal.pose, s);
  return s;
}

Scenario loadScenario(const std::string& path) { return parseScenario(readWholeFile(path), path); }

}  // namespace parksim
