#include "parksim/renders/scene/SceneBuilder.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <utility>

#include "parksim/core/io/NumberFormat.h"
#include "parksim/core/model/Ackermann.h"
#include "parksim/core/model/DiffDrive.h"

namespace parksim {

Rgba8 SceneStyle::colorFor(ObstacleKind kind) const {
  switch (kind) {
    case ObstacleKind::kWall: return wall;
    case ObstacleKind::kCurb: return curb;
    case ObstacleKind::kIsland: return island;
    case ObstacleKind::kBox: return box;
    case ObstacleKind::kBollard: return bollard;
    case ObstacleKind::kPillar: return pillar;
    case ObstacleKind::kParkedRobot: return parked_robot;
  }
  return box;
}

SceneStyle SceneStyle::scaled(double factor) const {
  SceneStyle s = *this;
  const auto f = static_cast<float>(factor);
  for (float* w :
       {&s.grid_px, &s.border_px, &s.tree_px, &s.path_px, &s.outline_px, &s.arrow_px, &s.text_px}) {
    *w *= f;
  }
  return s;
}

SceneStyle SceneStyle::forRobot(const RobotDef& ego) const {
  SceneStyle s = *this;
  const double scale = ego.sizeScale();
  s.grid_spacing_m *= scale;
  s.arrow_length_m *= scale;
  s.margin_m *= scale;
  return s;
}

namespace {

Eigen::Vector2d toWorld(const Pose2& pose, double x, double y) {
  const double c = std::cos(pose.theta);
  const double s = std::sin(pose.theta);
  return {pose.x + c * x - s * y, pose.y + s * x + c * y};
}

void growExtent(Extent2& e, const Eigen::Vector2d& p) {
  e.x_min = std::min(e.x_min, p.x());
  e.y_min = std::min(e.y_min, p.y());
  e.x_max = std::max(e.x_max, p.x());
  e.y_max = std::max(e.y_max, p.y());
}

void addGrid(Scene& scene, const LotBounds& lot, const SceneStyle& style) {
  const double step = style.grid_spacing_m;
  if (step <= 0.0) return;
  // Grid lines sit on multiples of the spacing, so they line up with the figures' axis ticks.
  for (double x = std::ceil(lot.x_min_m / step) * step; x <= lot.x_max_m + 1e-9; x += step) {
    scene.lines.push_back({{{x, lot.y_min_m, Layers::kGrid}, {x, lot.y_max_m, Layers::kGrid}},
                           style.grid,
                           style.grid_px,
                           false});
  }
  for (double y = std::ceil(lot.y_min_m / step) * step; y <= lot.y_max_m + 1e-9; y += step) {
    scene.lines.push_back({{{lot.x_min_m, y, Layers::kGrid}, {lot.x_max_m, y, Layers::kGrid}},
                           style.grid,
                           style.grid_px,
                           false});
  }
}

// A grid map's occupied and unknown cells, faintly, between the ground and its grid lines.
void addMapCells(Scene& scene, const Scenario& scenario, const SceneStyle& style) {
  for (const MapLayer& map : scenario.maps) {
    if (!map.grid) continue;
    const auto add = [&](const std::shared_ptr<const std::vector<CellRect>>& rects, Rgba8 color) {
      if (!rects || color.a == 0) return;
      for (const CellRect& r : *rects) {
        const auto c = map.grid->corners(r);
        scene.polygons.push_back({{c.begin(), c.end()}, Layers::kMap, color});
      }
    };
    add(map.unknown_cells, style.map_unknown);
    add(map.occupied_cells, style.map_occupied);
  }
}

// Tracking errors are sub-millimetre when all goes well: two decimals, and no "-0.00".
std::string formatOverlayLine2(const Overlay& o) {
  auto tidy = [](double v) { return std::abs(v) < 0.005 ? 0.0 : v; };
  return "tracking error " + padLeft(formatFixed(tidy(o.position_error_m * 1000.0), 2), 6) +
         " mm " + padLeft(formatFixed(tidy(radToDeg(o.heading_error_rad)), 2), 6) + "\u00b0";
}

}  // namespace

Scene buildLotScene(const Scenario& scenario, const SceneStyle& style,
                    std::span<const Pose2> obstacle_poses, std::span<const int> contacts) {
  Scene scene;
  scene.background = style.background;
  const LotBounds& lot = scenario.lot;
  Extent2 extent{lot.x_min_m, lot.y_min_m, lot.x_max_m, lot.y_max_m};

  scene.polygons.push_back({{{lot.x_min_m, lot.y_min_m},
                             {lot.x_max_m, lot.y_min_m},
                             {lot.x_max_m, lot.y_max_m},
                             {lot.x_min_m, lot.y_max_m}},
                            Layers::kGround,
                            style.lot});
  addMapCells(scene, scenario, style);
  addGrid(scene, lot, style);
  scene.lines.push_back(
      boxOutline(OrientedBox{extent.center(), {0.5 * extent.width(), 0.5 * extent.height()}, 0.0},
                 Layers::kGrid, style.lot_border, style.border_px));

  for (std::size_t i = 0; i < scenario.obstacles.size(); ++i) {
    const Obstacle& obstacle = scenario.obstacles[i];
    const bool touching =
        std::find(contacts.begin(), contacts.end(), static_cast<int>(i)) != contacts.end();
    const Rgba8 color = touching ? style.contact : style.colorFor(obstacle.kind);
    if (obstacle.shape == ObstacleShape::kBox) {
      SceneBox box{obstacle.box, 0.0, obstacle.height_m, color};
      if (i < obstacle_poses.size()) {
        box.footprint.center = {obstacle_poses[i].x, obstacle_poses[i].y};
        box.footprint.yaw = obstacle_poses[i].theta;
      }
      for (const Eigen::Vector2d& c : box.footprint.corners()) growExtent(extent, c);
      scene.boxes.push_back(box);
      continue;
    }
    // Round, polygonal and compound obstacles: their convex pieces (a compound obstacle's
    // parts, in one colour, so that they read as one), moved as the body moved from where the
    // scenario put it (the body's frame is the bounding rectangle's centre and yaw).
    for (std::vector<Eigen::Vector2d>& piece : convexPieces(obstacle, style.circle_segments)) {
      ScenePrism prism{std::move(piece), 0.0, obstacle.height_m, color};
      if (i < obstacle_poses.size()) {
        const Pose2 now = obstacle_poses[i];
        const double turn = now.theta - obstacle.box.yaw;
        const double c = std::cos(turn);
        const double s = std::sin(turn);
        for (Eigen::Vector2d& p : prism.footprint) {
          const Eigen::Vector2d d = p - obstacle.box.center;
          p = Eigen::Vector2d(now.x + c * d.x() - s * d.y(), now.y + s * d.x() + c * d.y());
        }
      }
      for (const Eigen::Vector2d& p : prism.footprint) growExtent(extent, p);
      scene.prisms.push_back(std::move(prism));
    }
  }

  // The goal footprint, where the robot must end, dashed so the robot parked on it shows.
  const ScenePolyline goal_outline = boxOutline(footprintAt(scenario.robot, scenario.goal.pose),
                                                Layers::kOutline, style.goal, style.outline_px);
  const double scale = scenario.robot.sizeScale();  // dashes of 8 mm for the study's robot
  for (ScenePolyline& dash : dashed(goal_outline, 0.008 * scale, 0.006 * scale)) {
    scene.lines.push_back(std::move(dash));
  }
  const double head = 0.3 * style.arrow_length_m;
  scene.arrows.push_back(
      {scenario.start, style.arrow_length_m, head, Layers::kArrow, style.start, style.arrow_px});
  scene.arrows.push_back(
      {scenario.goal.pose, style.arrow_length_m, head, Layers::kArrow, style.goal, style.arrow_px});
  for (const Pose2& p : {scenario.start, scenario.goal.pose}) {
    growExtent(extent, toWorld(p, style.arrow_length_m, 0.0));
  }

  extent.x_min -= style.margin_m;
  extent.y_min -= style.margin_m;
  extent.x_max += style.margin_m;
  extent.y_max += style.margin_m;
  scene.extent = extent;
  return scene;
}

void addRobot(Scene& scene, const RobotDef& robot, const Pose2& pose, const SceneStyle& style,
              double steer_rad) {
  // Drawn lengths are the study robot's, in proportion to this one's size.
  const double scale = robot.sizeScale();
  const double clearance = std::min(0.004 * scale, 0.1 * robot.height_m);
  scene.boxes.push_back(
      {footprintAt(robot, pose), clearance, robot.height_m - clearance, style.robot});
  const double wheel_width = std::min(0.008 * scale, 0.2 * robot.wheel_base_m);
  for (double side : {-1.0, 1.0}) {
    OrientedBox wheel;
    wheel.center = toWorld(pose, 0.0, side * 0.5 * robot.wheel_base_m);
    wheel.half_extents = {robot.wheel_radius_m, 0.5 * wheel_width};
    wheel.yaw = pose.theta;
    scene.boxes.push_back({wheel, 0.0, 2.0 * robot.wheel_radius_m, style.wheel});
  }
  if (robot.isCar()) {
    const FrontWheelAngles turned = ackermannAngles(robot, steer_rad);
    for (const auto& [side, angle] :
         {std::pair{-1.0, turned.right_rad}, std::pair{1.0, turned.left_rad}}) {
      OrientedBox wheel;
      wheel.center = toWorld(pose, robot.axle_distance_m, side * 0.5 * robot.wheel_base_m);
      wheel.half_extents = {robot.wheel_radius_m, 0.5 * wheel_width};
      wheel.yaw = pose.theta + angle;
      scene.boxes.push_back({wheel, 0.0, 2.0 * robot.wheel_radius_m, style.wheel});
    }
    // A car's wheels lie under its body (its track is narrower than its width), so a camera
    // from above would never show the steering: each wheel is drawn again as a flat shape on
    // the roof, like the heading marker, as schematic car drawings do.
    const std::size_t wheels = scene.boxes.size();
    for (std::size_t i = wheels - 4; i < wheels; ++i) {
      const std::array<Eigen::Vector2d, 4> c = scene.boxes[i].footprint.corners();
      scene.polygons.push_back(
          {{c.begin(), c.end()}, robot.height_m + 0.0005 * scale, style.wheel});
    }
  }
  // Heading marker: a triangle in the front part of the top face. It stays ahead of the
  // footprint's centre, which therefore shows the body colour (tests rely on it).
  const double front = robot.front_overhang_m;
  const double center = robot.footprintCenterOffset();
  const double tip = front - 0.1 * robot.length_m;
  const double base = center + 0.25 * robot.length_m;
  const double half_w = 0.25 * robot.width_m;
  scene.polygons.push_back(
      {{toWorld(pose, tip, 0.0), toWorld(pose, base, half_w), toWorld(pose, base, -half_w)},
       robot.height_m + 0.0005 * scale,
       style.robot_marker});
  scene.focus = Eigen::Vector3d(pose.x, pose.y, 0.0);
  scene.focus_scale = scale;
}

void addPath(Scene& scene, std::span<const Pose2> poses, double z_m, Rgba8 color, float width_px) {
  if (poses.size() < 2) return;
  ScenePolyline line{{}, color, width_px, false};
  line.points.reserve(poses.size());
  for (const Pose2& p : poses) line.points.emplace_back(p.x, p.y, z_m);
  scene.lines.push_back(std::move(line));
}

SceneLayers buildSceneLayers(const Scenario& scenario, const ViewState& view,
                             const SceneStyle& style) {
  SceneLayers layers;
  layers.back = buildLotScene(scenario, style, view.obstacle_poses, view.contacts);
  Scene& back = layers.back;
  Scene& front = layers.front;
  front.background = back.background;
  front.extent = back.extent;
  front.extent_top_m = back.extent_top_m;
  // The arrows are drawn after every line: they go to the front so the driven path stays
  // under them, as in one scene.
  front.arrows = std::move(back.arrows);
  back.arrows.clear();
  for (const Trajectory& edge : view.tree_edges) {
    ScenePolyline line{{}, style.tree, style.tree_px, false};
    line.points.reserve(edge.points.size());
    for (const TrajectoryPoint& p : edge.points) {
      line.points.emplace_back(p.pose.x, p.pose.y, Layers::kTree);
    }
    if (line.points.size() >= 2) back.lines.push_back(std::move(line));
  }
  addPath(back, view.planned_path, Layers::kPlanned, style.planned, style.path_px);
  addPath(front, view.executed_path, Layers::kExecuted, style.executed, style.path_px);
  if (view.robot) addRobot(front, scenario.robot, *view.robot, style, view.robot_steer_rad);
  if (view.reference) {
    // Above the body, so that in the top view a tracking error shows as the outline's offset
    // from the body rather than being hidden under it.
    front.lines.push_back(boxOutline(footprintAt(scenario.robot, *view.reference),
                                     scenario.robot.height_m + 0.001 * scenario.robot.sizeScale(),
                                     style.reference, style.outline_px));
  }
  if (view.overlay) {
    const Overlay& o = *view.overlay;
    const std::string line1 = o.title + (o.title.empty() ? "" : "   ") +
                              "t = " + padLeft(formatFixed(o.time_s, 2), 6) + " s";
    const float size = style.text_px;
    const double pad = 0.5 * size;
    front.texts.push_back({line1,
                           std::nullopt,
                           {pad, pad},
                           size,
                           style.text,
                           style.text_background,
                           HAlign::kLeft,
                           VAlign::kTop});
    front.texts.push_back({formatOverlayLine2(o),
                           std::nullopt,
                           {pad, pad + 1.35 * size},
                           size,
                           style.text,
                           style.text_background,
                           HAlign::kLeft,
                           VAlign::kTop});
  }
  return layers;
}

Scene buildScene(const Scenario& scenario, const ViewState& view, const SceneStyle& style) {
  SceneLayers layers = buildSceneLayers(scenario, view, style);
  appendScene(layers.back, layers.front);
  return std::move(layers.back);
}

std::vector<Pose2> samplePath(const Trajectory& trajectory, const RobotDef& robot,
                              double max_step_m, double max_turn_rad) {
  std::vector<Pose2> out;
  if (trajectory.points.empty()) return out;
  out.push_back(trajectory.points.front().pose);
  for (std::size_t i = 0; i + 1 < trajectory.points.size(); ++i) {
    const TrajectoryPoint& p = trajectory.points[i];
    const TrajectoryPoint& q = trajectory.points[i + 1];
    const double dt = q.t_s - p.t_s;
    const Twist twist = toTwist(p.wheels, robot);
    const double dist = std::abs(twist.v_mps) * dt;
    const double turn = std::abs(twist.omega_radps) * dt;
    const double pieces = std::ceil(std::max(dist / max_step_m, turn / max_turn_rad));
    const int n = static_cast<int>(std::clamp(pieces, 1.0, 10000.0));
    for (int k = 1; k < n; ++k) out.push_back(integrateExact(p.pose, twist, dt * k / n));
    out.push_back(q.pose);
  }
  return out;
}

}  // namespace parksim
