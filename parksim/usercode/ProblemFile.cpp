#include "parksim/usercode/ProblemFile.h"

#include "parksim/planner/base/PlanScenario.h"

namespace parksim {

namespace {

nlohmann::json pointJson(const Eigen::Vector2d& p) { return nlohmann::json::array({p.x(), p.y()}); }

nlohmann::json obstacleJson(const Obstacle& o, const RobotDef& robot) {
  nlohmann::json j = {{"name", o.name}, {"kind", toString(o.kind)}};
  switch (o.shape) {
    case ObstacleShape::kBox:
      j["shape"] = "box";
      j["center_m"] = pointJson(o.box.center);
      j["size_m"] = pointJson(2.0 * o.box.half_extents);
      j["yaw_rad"] = o.box.yaw;
      break;
    case ObstacleShape::kCircle:
      j["shape"] = "circle";
      j["center_m"] = pointJson(o.box.center);
      j["radius_m"] = o.radius_m;
      break;
    case ObstacleShape::kPolygon: {
      j["shape"] = "polygon";
      nlohmann::json vertices = nlohmann::json::array();
      for (const Eigen::Vector2d& v : o.vertices) vertices.push_back(pointJson(v));
      j["vertices_m"] = std::move(vertices);
      break;
    }
    case ObstacleShape::kCompound: {
      // Non-convex outlines and map cells: the convex parts (their union the shape)
      // and, where there is one, the outline (outer rings counter-clockwise, holes clockwise).
      j["shape"] = "compound";
      auto rings = [](const std::vector<std::vector<Eigen::Vector2d>>& polygons) {
        nlohmann::json out = nlohmann::json::array();
        for (const std::vector<Eigen::Vector2d>& polygon : polygons) {
          nlohmann::json ring = nlohmann::json::array();
          for (const Eigen::Vector2d& v : polygon) ring.push_back(pointJson(v));
          out.push_back(std::move(ring));
        }
        return out;
      };
      j["parts_m"] = rings(o.compound->parts);
      j["rings_m"] = rings(o.compound->rings);
      break;
    }
  }
  j["height_m"] = o.height_m;
  j["blocks_robot"] = blocksRobot(o, robot);
  return j;
}

}  // namespace

nlohmann::json poseJson(const Pose2& pose) {
  return {{"x_m", pose.x}, {"y_m", pose.y}, {"theta_rad", pose.theta}};
}

namespace {

// The robot: its drive, size and wheels, and a car's limits (RobotDef.h; a car's wheel_base_m
// is its track, its wheel limits its rear wheels').
nlohmann::json robotJson(const RobotDef& r) {
  nlohmann::json j = {{"drive", r.isCar() ? "car" : "differential"},
                      {"length_m", r.length_m},
                      {"width_m", r.width_m},
                      {"front_overhang_m", r.front_overhang_m},
                      {"wheel_base_m", r.wheel_base_m},
                      {"wheel_radius_m", r.wheel_radius_m},
                      {"max_wheel_speed_radps", r.max_wheel_speed_radps},
                      {"max_wheel_accel_radps2", r.max_wheel_accel_radps2},
                      {"height_m", r.height_m},
                      {"ground_clearance_m", r.ground_clearance_m}};
  if (r.isCar()) {
    j["track_m"] = r.wheel_base_m;
    j["axle_distance_m"] = r.axle_distance_m;
    j["max_steer_rad"] = r.max_steer_rad;
    j["max_steer_rate_radps"] = r.max_steer_rate_radps;
    j["max_speed_mps"] = r.max_speed_mps;
    j["max_accel_mps2"] = r.max_accel_mps2;
    j["max_curvature_1pm"] = r.maxCurvature();
  }
  return j;
}

}  // namespace

nlohmann::json worldJson(const Scenario& s) {
  const RobotDef& r = s.robot;
  nlohmann::json obstacles = nlohmann::json::array();
  for (const Obstacle& o : s.obstacles) obstacles.push_back(obstacleJson(o, r));
  return {
      {"name", s.name},
      {"file", s.source_path},
      {"lot",
       {{"x_min_m", s.lot.x_min_m},
        {"y_min_m", s.lot.y_min_m},
        {"x_max_m", s.lot.x_max_m},
        {"y_max_m", s.lot.y_max_m}}},
      {"robot", robotJson(r)},
      {"obstacles", std::move(obstacles)},
      {"start", poseJson(s.start)},
      {"goal",
       {{"pose", poseJson(s.goal.pose)},
        {"position_tolerance_m", s.goal.position_tolerance_m},
        {"heading_tolerance_rad", s.goal.heading_tolerance_rad},
        {"either_heading", s.goal.either_heading}}},
  };
}

nlohmann::json problemJson(const PlanningProblem& problem, const ParamMap& params) {
  const PlanSetup& setup = problem.setup;
  const TimingLimits& limits = problem.limits;
  nlohmann::json passed = nlohmann::json::object();
  for (const auto& [name, value] : params) passed[name] = value;
  return {
      {"format", kProblemFormat},
      {"world", worldJson(problem.scenario)},
      {"timing",
       {{"max_wheel_speed_radps", limits.max_wheel_speed_radps},
        {"max_wheel_accel_radps2", limits.max_wheel_accel_radps2},
        {"period_s", limits.period_s},
        {"start_jerk_radps3", limits.start_jerk_radps3}}},
      {"check", {{"resolution_m", setup.validation.resolution_m}}},
      {"budget",
       {{"max_iterations", setup.search.max_iterations},
        {"max_time_s", setup.search.max_time_s},
        {"seed", setup.search.seed}}},
      {"params", std::move(passed)},
  };
}

}  // namespace parksim
