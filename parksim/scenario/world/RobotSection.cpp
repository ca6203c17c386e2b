#include "parksim/scenario/world/RobotSection.h"

#include <charconv>

#include "parksim/core/geometry/Angle.h"
#include "parksim/core/io/NumberFormat.h"
#include "parksim/scenario/world/RobotReader.h"

namespace parksim {

namespace {

// Shortest text that reads back as the same double.
std::string roundTrip(double v) {
  char buf[64];
  const auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v);
  return ec == std::errc() ? std::string(buf, end) : std::string(".nan");
}

}  // namespace

std::vector<RobotSectionKey> robotSection(const RobotDef& r) {
  std::vector<RobotSectionKey> keys;
  const auto add = [&keys](const char* key, double v) { keys.push_back({key, roundTrip(v)}); };
  keys.push_back({"drive", r.isCar() ? "car" : "differential"});
  add("length", r.length_m);
  add("width", r.width_m);
  add("front_overhang", r.front_overhang_m);
  if (r.isCar()) {
    add("axle_distance", r.axle_distance_m);
    add("track", r.wheel_base_m);
    add("wheel_radius", r.wheel_radius_m);
    // Degrees to 15 digits: 40 degrees read back as 40, not 40.000000000000007.
    keys.push_back({"max_steer_deg", formatGeneral(radToDeg(r.max_steer_rad), 15)});
    keys.push_back({"max_steer_rate_degps", formatGeneral(radToDeg(r.max_steer_rate_radps), 15)});
    add("max_speed_mps", r.max_speed_mps);
    add("max_accel_mps2", r.max_accel_mps2);
  } else {
    add("wheel_base", r.wheel_base_m);
    add("wheel_radius", r.wheel_radius_m);
    add("max_wheel_speed_radps", r.max_wheel_speed_radps);
    add("max_wheel_accel_radps2", r.max_wheel_accel_radps2);
  }
  add("height", r.height_m);
  add("ground_clearance", r.ground_clearance_m);
  return keys;
}

void checkRobot(const RobotDef& robot) {
  YAML::Node map(YAML::NodeType::Map);
  for (const RobotSectionKey& k : robotSection(robot)) map[k.key] = YAML::Load(k.value);
  // No source: messages name the field alone (YamlField::fail).
  (void)readRobot(YamlField(map, "robot", 0, ""));
}

}  // namespace parksim
