#include "parksim/pages/LotData.h"

#include <cstdio>

namespace parksim {
namespace {

// Sides of the polygon a round obstacle is drawn as: round to the eye at any zoom a page allows.
constexpr int kCircleSegments = 48;

nlohmann::json pose(const Pose2& p) { return {p.x, p.y, p.theta}; }

}  // namespace

std::string cssColor(Rgba8 color) {
  char text[8];
  std::snprintf(text, sizeof text, "#%02x%02x%02x", color.r, color.g, color.b);
  return text;
}

nlohmann::json lotData(const Scenario& scenario, const SceneStyle& style) {
  nlohmann::json obstacles = nlohmann::json::array();
  for (const Obstacle& o : scenario.obstacles) {
    nlohmann::json points = nlohmann::json::array();
    for (const Eigen::Vector2d& p : outline(o, kCircleSegments)) {
      points.push_back(p.x());
      points.push_back(p.y());
    }
    obstacles.push_back({{"name", o.name},
                         {"kind", toString(o.kind)},
                         {"color", cssColor(style.colorFor(o.kind))},
                         {"blocks_robot", blocksRobot(o, scenario.robot)},
                         {"points", std::move(points)}});
  }
  const RobotDef& r = scenario.robot;
  const GoalRegion& g = scenario.goal;
  nlohmann::json data = {
      {"lot",
       {{"x_min", scenario.lot.x_min_m},
        {"y_min", scenario.lot.y_min_m},
        {"x_max", scenario.lot.x_max_m},
        {"y_max", scenario.lot.y_max_m}}},
      {"obstacles", std::move(obstacles)},
      {"robot",
       {{"length_m", r.length_m},
        {"width_m", r.width_m},
        {"front_overhang_m", r.front_overhang_m},
        {"wheel_base_m", r.wheel_base_m},
        {"wheel_radius_m", r.wheel_radius_m}}},
      {"start", pose(scenario.start)},
      {"goal",
       {{"pose", pose(g.pose)},
        {"position_tolerance_m", g.position_tolerance_m},
        {"heading_tolerance_rad", g.heading_tolerance_rad},
        {"either_heading", g.either_heading}}},
      {"style",
       {{"background", cssColor(style.background)},
        {"lot", cssColor(style.lot)},
        {"lot_border", cssColor(style.lot_border)},
        {"grid", cssColor(style.grid)},
        {"contact", cssColor(style.contact)},
        {"robot", cssColor(style.robot)},
        {"robot_marker", cssColor(style.robot_marker)},
        {"wheel", cssColor(style.wheel)},
        {"reference", cssColor(style.reference)},
        {"start", cssColor(style.start)},
        {"goal", cssColor(style.goal)},
        {"planned", cssColor(style.planned)},
        {"executed", cssColor(style.executed)},
        {"grid_spacing_m", style.grid_spacing_m}}},
  };
  // A car: the replay draws its front wheels, axle_distance ahead, turned by the record's
  // steering (a differential drive's page is what it was).
  if (r.isCar()) {
    data["robot"]["drive"] = "car";
    data["robot"]["axle_distance_m"] = r.axle_distance_m;
  }
  return data;
}

}  // namespace parksim
