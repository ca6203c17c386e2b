#include "parksim/renders/plots/Figures.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include "parksim/core/io/AtomicFile.h"
#include "parksim/core/io/Error.h"
#include "parksim/core/io/NumberFormat.h"
#include "parksim/renders/gl/Renderer.h"
#include "parksim/renders/image/PngEncoder.h"
#include "parksim/renders/plots/CSpace.h"
#include "parksim/renders/scene/SceneBuilder.h"
#include "parksim/renders/scene/SceneClip.h"

namespace parksim {

namespace {

// Room for axis labels and the title, as fractions of the data extent: label sizes are in
// pixels, the extent in metres, and figures are about 1.5:1, so fractions fit well enough.
void addAxesAndTitle(Scene& scene, const Extent2& data, const std::string& title,
                     const SceneStyle& style) {
  const double span = std::max(data.width(), data.height());
  const double tick = 0.012 * span;
  const float size = style.text_px;
  const float small = 0.85f * size;
  const double y0 = data.y_min;
  const double x0 = data.x_min;
  // Tick counts follow each side's share of the span, so a narrow extent gets no crowded labels.
  const auto ticks_for = [&](double side, double most) {
    return std::max(3, static_cast<int>(std::lround(most * side / span)));
  };
  const std::vector<double> xt = niceTicks(data.x_min, data.x_max, ticks_for(data.width(), 9.0));
  const std::vector<double> yt = niceTicks(data.y_min, data.y_max, ticks_for(data.height(), 9.0));
  const double x_step = xt.size() > 1 ? xt[1] - xt[0] : 1.0;
  const double y_step = yt.size() > 1 ? yt[1] - yt[0] : 1.0;
  for (double x : xt) {
    scene.lines.push_back({{{x, y0, Layers::kArrow}, {x, y0 - tick, Layers::kArrow}},
                           style.axis,
                           style.grid_px,
                           false});
    scene.texts.push_back(SceneText::worldLabel(formatTick(x, x_step),
                                                Eigen::Vector3d(x, y0 - 1.5 * tick, 0.0), small,
                                                style.axis, HAlign::kCenter, VAlign::kTop));
  }
  for (double y : yt) {
    scene.lines.push_back({{{x0, y, Layers::kArrow}, {x0 - tick, y, Layers::kArrow}},
                           style.axis,
                           style.grid_px,
                           false});
    scene.texts.push_back(SceneText::worldLabel(formatTick(y, y_step),
                                                Eigen::Vector3d(x0 - 1.5 * tick, y, 0.0), small,
                                                style.axis, HAlign::kRight, VAlign::kMiddle));
  }
  scene.texts.push_back(
      SceneText::worldLabel("x (m)", Eigen::Vector3d(data.center().x(), y0 - 0.07 * span, 0.0),
                            small, style.axis, HAlign::kCenter, VAlign::kTop));
  scene.texts.push_back(SceneText::worldLabel(
      "y (m)", Eigen::Vector3d(x0 - 0.075 * span, data.y_max + 0.03 * span, 0.0), small, style.axis,
      HAlign::kCenter, VAlign::kBottom));
  scene.texts.push_back(SceneText::worldLabel(
      title, Eigen::Vector3d(data.center().x(), data.y_max + 0.08 * span, 0.0), size, style.text,
      HAlign::kCenter, VAlign::kBottom));
  Extent2& e = scene.extent;
  e.x_min = std::min(e.x_min, data.x_min - 0.1 * span);
  e.y_min = std::min(e.y_min, data.y_min - 0.11 * span);
  e.y_max = std::max(e.y_max, data.y_max + 0.12 * span);
  e.x_max = std::max(e.x_max, data.x_max + 0.02 * span);
}

Extent2 lotExtent(const Scenario& s) {
  return {s.lot.x_min_m, s.lot.y_min_m, s.lot.x_max_m, s.lot.y_max_m};
}

// A figure of the lot shows the lot: what lies beyond it (obstacles, the parts of C-space
// slices and footprints past its edge) is clipped away before the axes go into the margin, and
// the frame is the lot with the usual ground margin (as buildLotScene frames a lot with nothing
// outside, so such figures are unchanged).
void clipToLot(Scene& scene, const Scenario& scenario, const SceneStyle& style) {
  const Extent2 lot = lotExtent(scenario);
  clipToArea(scene, lot);
  const double m = style.margin_m;
  scene.extent = {lot.x_min - m, lot.y_min - m, lot.x_max + m, lot.y_max + m};
}

void addLabel(Scene& scene, const std::string& text, const Eigen::Vector2d& at, Rgba8 color,
              const SceneStyle& style, HAlign h = HAlign::kLeft, VAlign v = VAlign::kBottom) {
  scene.texts.push_back({text, Eigen::Vector3d(at.x(), at.y(), 0.0), Eigen::Vector2d::Zero(),
                         0.85f * style.text_px, color, style.text_background, h, v});
}

// A label at `offset` from a marker, moved to the marker's other side along x or y where it
// would leave the lot (clipping would drop it: a goal by the lot's top edge keeps its label).
void addMarkerLabel(Scene& scene, const std::string& text, const Pose2& marker,
                    const Eigen::Vector2d& offset, const Extent2& lot, Rgba8 color,
                    const SceneStyle& style, HAlign h, VAlign v) {
  Eigen::Vector2d at(marker.x + offset.x(), marker.y + offset.y());
  if (at.x() < lot.x_min || at.x() > lot.x_max) {
    at.x() = marker.x - offset.x();
    h = h == HAlign::kLeft ? HAlign::kRight : h == HAlign::kRight ? HAlign::kLeft : h;
  }
  if (at.y() < lot.y_min || at.y() > lot.y_max) {
    at.y() = marker.y - offset.y();
    v = v == VAlign::kTop ? VAlign::kBottom : v == VAlign::kBottom ? VAlign::kTop : v;
  }
  addLabel(scene, text, at, color, style, h, v);
}

// Outlines along a path: at the start, whenever the robot has moved or turned enough since the
// last one, and at the end.
void addFootprints(Scene& scene, const RobotDef& robot, const std::vector<Pose2>& path,
                   double spacing_m, double turn_rad, Rgba8 color, float width_px) {
  if (path.empty()) return;
  const Pose2* last = nullptr;
  double travelled = 0.0;
  for (std::size_t i = 0; i < path.size(); ++i) {
    if (i > 0) travelled += positionDistance(path[i - 1], path[i]);
    const bool due = last == nullptr || travelled >= spacing_m ||
                     headingDistance(*last, path[i]) >= turn_rad || i + 1 == path.size();
    if (!due) continue;
    scene.lines.push_back(
        boxOutline(footprintAt(robot, path[i]), Layers::kOutline, color, width_px));
    last = &path[i];
    travelled = 0.0;
  }
}

Rgba8 darker(Rgba8 c, double t) { return mix(c, rgb(0, 0, 0), t); }

}  // namespace

Scene buildLotMapFigure(const Scenario& scenario, const SceneStyle& style) {
  Scene scene = buildLotScene(scenario, style);
  const double a = style.arrow_length_m;
  addMarkerLabel(scene, "start", scenario.start, {0.3 * a, -0.3 * a}, lotExtent(scenario),
                 style.start, style, HAlign::kLeft, VAlign::kTop);
  addMarkerLabel(scene, "goal", scenario.goal.pose, {0.5 * a, 0.6 * a}, lotExtent(scenario),
                 style.goal, style, HAlign::kLeft, VAlign::kBottom);
  clipToLot(scene, scenario, style);
  addAxesAndTitle(scene, lotExtent(scenario),
                  "Lot map: " + scenario.name + " (Fig. 3): start red, goal green", style);
  return scene;
}

Scene buildSteeringFigure(const Scenario& scenario, const SteeringExample& ex,
                          const SceneStyle& style) {
  const RobotDef& robot = scenario.robot;
  const std::vector<Pose2> fixed = samplePath(ex.fixed_horizon, robot);
  const std::vector<Pose2> to_goal = samplePath(ex.to_goal, robot);
  Extent2 data{ex.start.x, ex.start.y, ex.start.x, ex.start.y};
  auto grow = [&](const Pose2& p) {
    for (const Eigen::Vector2d& c : footprintAt(robot, p).corners()) {
      data.x_min = std::min(data.x_min, c.x());
      data.y_min = std::min(data.y_min, c.y());
      data.x_max = std::max(data.x_max, c.x());
      data.y_max = std::max(data.y_max, c.y());
    }
  };
  for (const Pose2& p : fixed) grow(p);
  for (const Pose2& p : to_goal) grow(p);
  grow(ex.target);
  const double pad = 0.15 * std::max(data.width(), data.height()) + 0.02;
  data = {data.x_min - pad, data.y_min - pad, data.x_max + pad, data.y_max + pad};

  Scene scene;
  scene.background = style.background;
  scene.extent = data;
  scene.polygons.push_back({{{data.x_min, data.y_min},
                             {data.x_max, data.y_min},
                             {data.x_max, data.y_max},
                             {data.x_min, data.y_max}},
                            Layers::kGround,
                            style.lot});
  const std::vector<double> grid = niceTicks(0.0, std::max(data.width(), data.height()), 10);
  const double step = grid.size() > 1 ? grid[1] : 0.1;
  for (double x = std::ceil(data.x_min / step) * step; x <= data.x_max; x += step) {
    scene.lines.push_back({{{x, data.y_min, Layers::kGrid}, {x, data.y_max, Layers::kGrid}},
                           style.grid,
                           style.grid_px,
                           false});
  }
  for (double y = std::ceil(data.y_min / step) * step; y <= data.y_max; y += step) {
    scene.lines.push_back({{{data.x_min, y, Layers::kGrid}, {data.x_max, y, Layers::kGrid}},
                           style.grid,
                           style.grid_px,
                           false});
  }
  ScenePolyline goal_line{{}, style.executed, style.path_px, false};
  for (const Pose2& p : to_goal) goal_line.points.emplace_back(p.x, p.y, Layers::kPlanned);
  for (ScenePolyline& dash : dashed(goal_line, 0.012, 0.008))
    scene.lines.push_back(std::move(dash));
  addPath(scene, fixed, Layers::kExecuted, style.planned, 1.3f * style.path_px);

  scene.lines.push_back(
      boxOutline(footprintAt(robot, ex.start), Layers::kOutline, style.start, style.outline_px));
  if (!fixed.empty()) {
    scene.lines.push_back(boxOutline(footprintAt(robot, fixed.back()), Layers::kOutline,
                                     style.planned, style.outline_px));
  }
  for (ScenePolyline& dash : dashed(boxOutline(footprintAt(robot, ex.target), Layers::kOutline,
                                               style.goal, style.outline_px),
                                    0.008, 0.006)) {
    scene.lines.push_back(std::move(dash));
  }
  const double a =
      0.6 * std::min(style.arrow_length_m, 0.25 * std::max(data.width(), data.height()));
  scene.arrows.push_back({ex.start, a, 0.3 * a, Layers::kArrow, style.start, style.arrow_px});
  scene.arrows.push_back({ex.target, a, 0.3 * a, Layers::kArrow, style.goal, style.arrow_px});

  const double span = std::max(data.width(), data.height());
  addLabel(scene, "solid: fixed horizon (" + formatFixed(ex.fixed_horizon.duration(), 1) + " s)",
           {data.x_min + 0.03 * span, data.y_max - 0.03 * span}, style.planned, style,
           HAlign::kLeft, VAlign::kTop);
  addLabel(scene, "dashed: to goal (" + formatFixed(ex.to_goal.duration(), 1) + " s)",
           {data.x_min + 0.03 * span, data.y_max - 0.09 * span}, style.executed, style,
           HAlign::kLeft, VAlign::kTop);
  clipToArea(scene, data);  // a safety net: the extent is made to hold every path and marker
  addAxesAndTitle(scene, data, "Move-to-pose steering in both modes (Fig. 2)", style);
  return scene;
}

Scene buildCSpaceSliceFigure(const Scenario& scenario, double theta_rad, const SceneStyle& style) {
  Scene scene = buildLotScene(scenario, style);
  const Rgba8 fill = withAlpha(style.cspace, 80);
  const Rgba8 edge = darker(style.cspace, 0.2);
  const Rgba8 compound_fill = mix(style.lot, style.cspace, 80.0 / 255.0);
  for (const Obstacle& obstacle : scenario.obstacles) {
    // Obstacles that pass under the chassis are no C-space obstacles (blocksRobot).
    if (!blocksRobot(obstacle, scenario.robot)) continue;
    if (obstacle.shape == ObstacleShape::kCompound) {
      // The union of the parts' slices: opaque and without outlines, so that where the parts'
      // slices overlap nothing shows.
      for (auto& slice : cspaceSlices(obstacle, scenario.robot, theta_rad)) {
        scene.polygons.push_back({std::move(slice), Layers::kCSpace, compound_fill});
      }
      continue;
    }
    const std::vector<Eigen::Vector2d> slice = cspaceSlice(obstacle, scenario.robot, theta_rad);
    scene.polygons.push_back({slice, Layers::kCSpace, fill});
    ScenePolyline outline{{}, edge, style.outline_px * 1.3f, true};
    for (const Eigen::Vector2d& p : slice)
      outline.points.emplace_back(p.x(), p.y(), Layers::kOutline);
    scene.lines.push_back(std::move(outline));
  }
  // A footprint at this heading beside the lot's start, with its reference point marked, shows
  // what the slices are made of.
  const Pose2 example{scenario.start.x, scenario.start.y, theta_rad};
  scene.lines.push_back(boxOutline(footprintAt(scenario.robot, example), Layers::kOutline,
                                   style.footprint, style.outline_px));
  const double r = 0.006;
  scene.lines.push_back(
      {{{example.x - r, example.y, Layers::kArrow}, {example.x + r, example.y, Layers::kArrow}},
       style.footprint,
       style.outline_px,
       false});
  scene.lines.push_back(
      {{{example.x, example.y - r, Layers::kArrow}, {example.x, example.y + r, Layers::kArrow}},
       style.footprint,
       style.outline_px,
       false});
  // The lot bounds the reference point: C-space beyond it is no part of the problem.
  clipToLot(scene, scenario, style);
  addAxesAndTitle(scene, lotExtent(scenario),
                  "C-space obstacles at heading " + formatFixed(radToDeg(theta_rad), 0) +
                      "\u00b0 (Fig. 5): exact Minkowski slices",
                  style);
  return scene;
}

Scene buildCSpaceStackFigure(const Scenario& scenario, int slices, const SceneStyle& style) {
  slices = std::clamp(slices, 1, 720);
  const LotBounds& lot = scenario.lot;
  Scene scene;
  scene.background = style.background;
  scene.extent = lotExtent(scenario);
  const double top = 0.5 * std::max(lot.x_max_m - lot.x_min_m, lot.y_max_m - lot.y_min_m);
  scene.extent_top_m = top;
  auto height_of = [&](double theta) { return (wrapAngle(theta) + kPi) / (2.0 * kPi) * top; };

  scene.polygons.push_back({{{lot.x_min_m, lot.y_min_m},
                             {lot.x_max_m, lot.y_min_m},
                             {lot.x_max_m, lot.y_max_m},
                             {lot.x_min_m, lot.y_max_m}},
                            Layers::kGround,
                            style.lot});
  for (const Obstacle& o : scenario.obstacles) {
    for (auto& piece : convexPieces(o, style.circle_segments)) {
      scene.polygons.push_back({std::move(piece), Layers::kGrid, style.colorFor(o.kind)});
    }
  }
  const Rgba8 cool = rgb(60, 110, 200);
  for (int k = 0; k < slices; ++k) {
    const double theta = -kPi + 2.0 * kPi * (k + 0.5) / slices;
    const double z = height_of(theta);
    // Cyclic colours: -180 and +180 degrees are the same heading and get the same colour.
    const Rgba8 color = mix(cool, style.cspace, 0.5 * (1.0 + std::cos(theta)));
    for (const Obstacle& o : scenario.obstacles) {
      if (!blocksRobot(o, scenario.robot)) continue;
      if (o.shape == ObstacleShape::kCompound) {
        // The parts' slices, without outlines (their seams are no edges of the union).
        for (auto& slice : cspaceSlices(o, scenario.robot, theta)) {
          scene.polygons.push_back({std::move(slice), z, color});
        }
        continue;
      }
      const std::vector<Eigen::Vector2d> slice = cspaceSlice(o, scenario.robot, theta);
      scene.polygons.push_back({slice, z, color});
      ScenePolyline outline{{}, darker(color, 0.45), style.tree_px, true};
      for (const Eigen::Vector2d& p : slice) outline.points.emplace_back(p.x(), p.y(), z + 1e-4);
      scene.lines.push_back(std::move(outline));
    }
  }
  // Start and goal as points of (x, y, theta): arrows at the height of their heading.
  const double a = style.arrow_length_m;
  scene.arrows.push_back(
      {scenario.start, a, 0.3 * a, height_of(scenario.start.theta), style.start, style.arrow_px});
  scene.arrows.push_back({scenario.goal.pose, a, 0.3 * a, height_of(scenario.goal.pose.theta),
                          style.goal, style.arrow_px});
  // C-space is the lot times the headings: slices (and obstacles) beyond the lot are cut off
  // at its edge, so the stack is a block the heading axis stands beside.
  clipToArea(scene, scene.extent);
  // The heading axis at the lot's front-left corner, where no stack hides it.
  const Eigen::Vector2d axis(lot.x_min_m, lot.y_min_m);
  scene.lines.push_back(
      {{{axis.x(), axis.y(), 0.0}, {axis.x(), axis.y(), top}}, style.axis, style.border_px, false});
  for (int deg = -180; deg <= 180; deg += 90) {
    const double z = (deg + 180.0) / 360.0 * top;
    const double tick = 0.03;
    scene.lines.push_back({{{axis.x(), axis.y(), z}, {axis.x() - tick, axis.y(), z}},
                           style.axis,
                           style.border_px,
                           false});
    scene.texts.push_back(SceneText::worldLabel(
        std::to_string(deg) + "\u00b0", Eigen::Vector3d(axis.x() - 1.5 * tick, axis.y(), z),
        0.85f * style.text_px, style.axis, HAlign::kRight, VAlign::kMiddle));
  }
  scene.texts.push_back(
      SceneText::worldLabel("\u03b8", Eigen::Vector3d(axis.x(), axis.y(), top * 1.04),
                            style.text_px, style.axis, HAlign::kCenter, VAlign::kBottom));
  scene.texts.push_back({"C-space obstacles over (x, y, \u03b8), " + std::to_string(slices) +
                             " exact slices (Fig. 6)",
                         std::nullopt, Eigen::Vector2d(0.6 * style.text_px, 0.6 * style.text_px),
                         style.text_px, style.text, style.text_background, HAlign::kLeft,
                         VAlign::kTop});
  return scene;
}

Scene buildPlanFigure(const Scenario& scenario, const PlanFigure& plan, const FigureDef& def,
                      const SceneStyle& style) {
  const std::vector<Pose2> path = samplePath(plan.trajectory, scenario.robot);
  ViewState view;
  view.tree_edges = plan.tree_edges;
  Scene scene = buildScene(scenario, view, style);
  addPath(scene, path, Layers::kPlanned, style.planned, style.path_px);
  addFootprints(scene, scenario.robot, path, def.footprint_spacing_m, def.footprint_turn_rad,
                style.footprint, style.outline_px);
  for (const Pose2& w : plan.waypoints) {
    const double r = 0.008;
    scene.lines.push_back(boxOutline(OrientedBox{{w.x, w.y}, {r, r}, kPi / 4}, Layers::kArrow,
                                     style.waypoint, style.outline_px * 1.5f));
  }
  clipToLot(scene, scenario, style);
  addAxesAndTitle(scene, lotExtent(scenario), plan.caption, style);
  return scene;
}

Scene buildLot3dFigure(const Scenario& scenario, const PlanFigure* plan, const SceneStyle& style) {
  Scene scene = buildLotScene(scenario, style);
  if (plan != nullptr) {
    addPath(scene, samplePath(plan->trajectory, scenario.robot), Layers::kPlanned, style.planned,
            style.path_px);
  }
  addRobot(scene, scenario.robot, scenario.start, style);
  scene.focus.reset();
  scene.texts.push_back({"Lot " + scenario.name + " in perspective", std::nullopt,
                         Eigen::Vector2d(0.6 * style.text_px, 0.6 * style.text_px), style.text_px,
                         style.text, style.text_background, HAlign::kLeft, VAlign::kTop});
  return scene;
}

CameraDef figureCamera(const std::string& figure_name) {
  if (figure_name == "cspace_stack") {
    return {.mode = CameraMode::kPerspective,
            .fov_y_deg = 38.0,
            .azimuth_deg = -62.0,
            .elevation_deg = 32.0,
            .fill = 0.95};
  }
  if (figure_name == "lot_3d") {
    return {.mode = CameraMode::kPerspective,
            .fov_y_deg = 38.0,
            .azimuth_deg = -70.0,
            .elevation_deg = 42.0};
  }
  return {};
}

namespace {

class FigureWriter {
 public:
  FigureWriter(const FigureDef& def, std::string dir)
      : dir_(std::move(dir)), renderer_(renderDef(def)) {
    ensureDirectory(dir_);
  }

  std::string write(const std::string& name, const Scene& scene, const CameraDef& camera) {
    renderer_.render(scene, camera, image_);
    const std::string path = dir_ + "/" + name + ".png";
    // Figures are written once: stb's slower, smaller encoding is worth it.
    writePng(path, image_, PngCompression::kSmall);
    return path;
  }

 private:
  static RenderDef renderDef(const FigureDef& def) {
    RenderDef r;
    r.width_px = def.width_px;
    r.height_px = def.height_px;
    r.msaa_samples = def.msaa_samples;
    r.context = def.context;
    return r;
  }

  std::string dir_;
  Renderer renderer_;
  RgbImage image_;
};

}  // namespace

std::vector<std::string> writeFigures(const Scenario& scenario, const FigureInputs& inputs,
                                      const FigureDef& def, const std::string& dir) {
  const FigureSelection& chosen = def.figures;
  std::vector<std::string> written;
  if (chosen.empty()) return written;
  const SceneStyle style = def.style.scaled(styleScaleFor(def.height_px)).forRobot(scenario.robot);
  FigureWriter writer(def, dir);
  auto put = [&](const std::string& name, const Scene& scene) {
    written.push_back(writer.write(name, scene, figureCamera(name)));
  };
  if (chosen.contains("lot_map")) put("lot_map", buildLotMapFigure(scenario, style));
  if (inputs.steering && chosen.contains("steering")) {
    put("steering", buildSteeringFigure(scenario, *inputs.steering, style));
  }
  if (chosen.contains("cspace_slice")) {
    put("cspace_slice", buildCSpaceSliceFigure(scenario, def.cspace_heading_rad, style));
  }
  if (chosen.contains("cspace_stack")) {
    put("cspace_stack", buildCSpaceStackFigure(scenario, def.cspace_slices, style));
  }
  for (const PlanFigure& plan : inputs.plans) {
    if (chosen.contains("plan")) {
      put("plan_" + plan.name, buildPlanFigure(scenario, plan, def, style));
    }
  }
  if (inputs.tracking && chosen.contains("tracking_error")) {
    CameraDef plot_camera;
    plot_camera.fill = 1.0;
    written.push_back(
        writer.write("tracking_error",
                     buildTrackingPlot(*inputs.tracking, "Tracking error: " + scenario.name,
                                       def.width_px, def.height_px, style),
                     plot_camera));
  }
  if (chosen.contains("lot_3d")) {
    put("lot_3d",
        buildLot3dFigure(scenario, inputs.plans.empty() ? nullptr : &inputs.plans.front(), style));
  }
  return written;
}

void writeTrackingPlot(const TrackingSeries& series, const std::string& title, const FigureDef& def,
                       const std::string& path) {
  const SceneStyle style = def.style.scaled(styleScaleFor(def.height_px));
  RenderDef r;
  r.width_px = def.width_px;
  r.height_px = def.height_px;
  r.msaa_samples = def.msaa_samples;
  r.context = def.context;
  Renderer renderer(r);
  RgbImage image;
  CameraDef camera;
  camera.fill = 1.0;
  renderer.render(buildTrackingPlot(series, title, def.width_px, def.height_px, style), camera,
                  image);
  writePng(path, image, PngCompression::kSmall);
}

}  // namespace parksim
