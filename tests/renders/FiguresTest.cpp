#include "parksim/renders/plots/Figures.h"

#include <gtest/gtest.h>

#include <set>

#include "RenderTestUtil.h"
#include "parksim/renders/gl/Renderer.h"
#include "parksim/renders/image/PngEncoder.h"
#include "parksim/renders/plots/CSpace.h"
#include "parksim/renders/scene/SceneBuilder.h"
#include "parksim/renders/scene/SceneClip.h"
#include "parksim/scenario/world/ScenarioReader.h"

namespace parksim {
namespace {

using rendertest::testLot;

int distinctColours(const RgbImage& img) {
  std::set<std::uint32_t> colours;
  for (std::size_t i = 0; i < img.pixels.size(); i += 3) {
    colours.insert(img.pixels[i] << 16 | img.pixels[i + 1] << 8 | img.pixels[i + 2]);
  }
  return static_cast<int>(colours.size());
}

TEST(FiguresTest, CSpaceSliceFigureHoldsOneExactSlicePerObstacle) {
  const Scenario s = testLot();
  const SceneStyle style;
  const double theta = degToRad(-60.0);
  const Scene scene = buildCSpaceSliceFigure(s, theta, style);
  std::size_t slices = 0;
  for (const ScenePolygon& p : scene.polygons) {
    if (p.color.a == 255) continue;  // the lot surface
    ASSERT_LT(slices, s.obstacles.size());
    // Clipped to the lot (wall_1's slice reaches past its top edge).
    EXPECT_EQ(p.points, clipPolygon(cspaceSlice(s.obstacles[slices].box, s.robot, theta),
                                    {s.lot.x_min_m, s.lot.y_min_m, s.lot.x_max_m, s.lot.y_max_m}));
    ++slices;
  }
  EXPECT_EQ(slices, s.obstacles.size());
}

TEST(FiguresTest, CSpaceStackPutsHeadingOnTheHeightAxis) {
  const Scenario s = testLot();
  const Scene scene = buildCSpaceStackFigure(s, 12, SceneStyle{});
  EXPECT_GT(scene.extent_top_m, 0.0);
  std::set<double> heights;
  for (const ScenePolygon& p : scene.polygons) {
    if (p.z_m > 0.001) heights.insert(p.z_m);
  }
  ASSERT_EQ(heights.size(), 12u);
  EXPECT_NEAR(*heights.begin(), scene.extent_top_m / 24.0, 1e-12);  // -180 + 15 degrees
}

TEST(FiguresTest, WritesTheStudysFiguresAsNonBlankImages) {
  const Scenario s = testLot();
  FigureDef def;
  def.width_px = 600;
  def.height_px = 400;
  def.cspace_slices = 18;
  FigureInputs inputs;
  const Trajectory drive = rendertest::sampleDrive(s.robot, s.start);
  SteeringExample steering;
  steering.start = s.start;
  steering.to_goal = drive;
  steering.target = drive.points.back().pose;
  steering.fixed_horizon.points.assign(drive.points.begin(), drive.points.begin() + 11);
  steering.fixed_horizon.points.back().wheels = {};
  inputs.steering = steering;
  PlanFigure plan;
  plan.name = "test";
  plan.caption = "a test plan";
  plan.trajectory = drive;
  plan.waypoints = {drive.points.front().pose, drive.points[20].pose, drive.points.back().pose};
  plan.tree_edges = {drive,
                     rendertest::drive(s.robot, s.start, std::vector<Twist>(10, {0.1, -1.0}))};
  inputs.plans.push_back(plan);
  inputs.tracking = TrackingSeries{{0.0, 1.0, 2.0}, {0.0, 0.002, 0.001}, {0.0, 0.01, -0.01}};

  const std::string dir = rendertest::outputDir("FiguresTest") + "/figures";
  const std::vector<std::string> written = writeFigures(s, inputs, def, dir);
  const std::vector<std::string> names = {"lot_map",      "steering",  "cspace_slice",
                                          "cspace_stack", "plan_test", "tracking_error",
                                          "lot_3d"};
  ASSERT_EQ(written.size(), names.size());
  for (std::size_t i = 0; i < names.size(); ++i) {
    EXPECT_EQ(written[i], dir + "/" + names[i] + ".png");
    const RgbImage img = readPng(written[i]);
    EXPECT_EQ(img.width, 600);
    EXPECT_EQ(img.height, 400);
    EXPECT_GT(distinctColours(img), 20) << names[i];
  }
}

// Obstacles beyond the lot, across its edges, a goal arrow pointing out of it.
Scenario outsideLot() {
  return loadScenario(parksim::testing::sourceDir() + "/tests/renders/outside_lot.yaml");
}

Extent2 lotOf(const Scenario& s) {
  return {s.lot.x_min_m, s.lot.y_min_m, s.lot.x_max_m, s.lot.y_max_m};
}

// Everything drawn in the world lies in `area`, apart from what the axes put around it: tick
// lines in the axis colour, and tick labels, axis names and the title (axis or text colour, no
// background box). Labels of the data ("start", "goal") have a background box and must be in.
void expectOnlyAxesOutside(const Scene& scene, const Extent2& area, const SceneStyle& style,
                           const std::string& figure) {
  constexpr double kTol = 1e-12;
  auto in = [&](double x, double y) {
    return x >= area.x_min - kTol && x <= area.x_max + kTol && y >= area.y_min - kTol &&
           y <= area.y_max + kTol;
  };
  for (const ScenePolygon& p : scene.polygons) {
    for (const Eigen::Vector2d& q : p.points) EXPECT_TRUE(in(q.x(), q.y())) << figure << " polygon";
  }
  for (const SceneBox& b : scene.boxes) {
    for (const Eigen::Vector2d& q : b.footprint.corners())
      EXPECT_TRUE(in(q.x(), q.y())) << figure << " box";
  }
  for (const ScenePrism& p : scene.prisms) {
    for (const Eigen::Vector2d& q : p.footprint)
      EXPECT_TRUE(in(q.x(), q.y())) << figure << " prism";
  }
  for (const ScenePolyline& l : scene.lines) {
    if (l.color == style.axis) continue;
    for (const Eigen::Vector3d& q : l.points) EXPECT_TRUE(in(q.x(), q.y())) << figure << " line";
  }
  for (const SceneArrow& a : scene.arrows) {
    EXPECT_TRUE(in(a.pose.x, a.pose.y)) << figure << " arrow tail";
    EXPECT_TRUE(in(a.pose.x + a.length_m * std::cos(a.pose.theta),
                   a.pose.y + a.length_m * std::sin(a.pose.theta)))
        << figure << " arrow tip";
  }
  for (const SceneText& t : scene.texts) {
    if (!t.world || in(t.world->x(), t.world->y())) continue;
    EXPECT_TRUE((t.color == style.axis || t.color == style.text) && t.background.a == 0)
        << figure << " text '" << t.text << "' outside";
  }
}

TEST(FiguresTest, FiguresWithAxesDrawNothingButTheAxesOutsideTheirPlotArea) {
  const Scenario s = outsideLot();
  const SceneStyle style;
  const Extent2 lot = lotOf(s);
  // A plan that backs out of the lot's left edge: its path and footprints are cut there.
  PlanFigure plan;
  plan.name = "out";
  plan.trajectory = rendertest::drive(s.robot, s.start, std::vector<Twist>(30, {-0.1, 0.0}));
  plan.tree_edges = {plan.trajectory};
  plan.waypoints = {plan.trajectory.points.back().pose};
  const Scene lot_map = buildLotMapFigure(s, style);
  expectOnlyAxesOutside(lot_map, lot, style, "lot_map");
  expectOnlyAxesOutside(buildCSpaceSliceFigure(s, degToRad(-60.0), style), lot, style,
                        "cspace_slice");
  expectOnlyAxesOutside(buildCSpaceStackFigure(s, 6, style), lot, style, "cspace_stack");
  expectOnlyAxesOutside(buildPlanFigure(s, plan, FigureDef{}, style), lot, style, "plan");
  SteeringExample steering;
  steering.start = s.start;
  steering.target = plan.trajectory.points.back().pose;
  steering.to_goal = plan.trajectory;
  const Scene steer = buildSteeringFigure(s, steering, style);
  const std::vector<Eigen::Vector2d>& frame = steer.polygons.front().points;  // its data extent
  expectOnlyAxesOutside(steer, {frame[0].x(), frame[0].y(), frame[2].x(), frame[2].y()}, style,
                        "steering");

  // What is left of the world: the obstacle inside as it was, the two across the lot's edges cut
  // at it, nothing of those wholly outside; the goal arrow ends on the lot's edge.
  ASSERT_EQ(lot_map.boxes.size(), 1u);
  EXPECT_EQ(lot_map.boxes[0].footprint.center, Eigen::Vector2d(0.3, 0.3));
  ASSERT_EQ(lot_map.prisms.size(), 2u);
  for (const ScenePrism& p : lot_map.prisms) {
    EXPECT_TRUE(std::any_of(p.footprint.begin(), p.footprint.end(), [&](const Eigen::Vector2d& q) {
      return q.x() == lot.x_min || q.x() == lot.x_max || q.y() == lot.y_max;
    }));
  }
  ASSERT_EQ(lot_map.arrows.size(), 2u);
  EXPECT_NEAR(lot_map.arrows[1].length_m, s.goal.pose.y - lot.y_min, 1e-12);
  // The frame is the lot and its ground margin: the obstacles outside do not widen it.
  EXPECT_EQ(lot_map.extent.x_max, lot.x_max + style.margin_m);
}

TEST(FiguresTest, ClippingAWorldWithNothingOutsideChangesNothing) {
  Scenario s = testLot();
  s.goal.pose = {1.5, 0.3, degToRad(90.0)};  // the study's goal arrow points out of the lot
  const SceneStyle style;
  const Scene before = buildLotScene(s, style);
  Scene after = before;
  clipToArea(after, lotOf(s));
  ASSERT_EQ(after.boxes.size(), before.boxes.size());
  for (std::size_t i = 0; i < before.boxes.size(); ++i) {
    EXPECT_EQ(after.boxes[i].footprint.corners(), before.boxes[i].footprint.corners());
  }
  EXPECT_TRUE(after.prisms.empty());
  ASSERT_EQ(after.polygons.size(), before.polygons.size());
  ASSERT_EQ(after.lines.size(), before.lines.size());
  for (std::size_t i = 0; i < before.lines.size(); ++i) {
    EXPECT_EQ(after.lines[i].points, before.lines[i].points);
    EXPECT_EQ(after.lines[i].closed, before.lines[i].closed);
  }
  ASSERT_EQ(after.arrows.size(), before.arrows.size());
  for (std::size_t i = 0; i < before.arrows.size(); ++i) {
    EXPECT_EQ(after.arrows[i].length_m, before.arrows[i].length_m);
  }
}

TEST(FiguresTest, StartAndGoalLabelsByTheLotsEdgeMoveInsideInsteadOfVanishing) {
  Scenario s = testLot();
  s.goal.pose = {1.79, 1.17, degToRad(180.0)};  // by the top-right corner
  s.start = {0.1, 0.005, degToRad(90.0)};       // on the bottom edge
  const Scene scene = buildLotMapFigure(s, SceneStyle{});
  int found = 0;
  for (const SceneText& t : scene.texts) {
    if (t.text != "start" && t.text != "goal") continue;
    ++found;
    ASSERT_TRUE(t.world.has_value());
    const Pose2& marker = t.text == "goal" ? s.goal.pose : s.start;
    EXPECT_TRUE(s.lot.contains(t.world->x(), t.world->y())) << t.text;
    // Moved to the marker's other side, aligned to grow away from the edge.
    if (t.text == "goal") {
      EXPECT_LT(t.world->x(), marker.x);
      EXPECT_EQ(t.h_align, HAlign::kRight);
      EXPECT_LT(t.world->y(), marker.y);
      EXPECT_EQ(t.v_align, VAlign::kTop);
    } else {
      EXPECT_GT(t.world->y(), marker.y);
      EXPECT_EQ(t.v_align, VAlign::kBottom);
    }
  }
  EXPECT_EQ(found, 2);
}

// Rendered: the margin around the plot area, where the axes are, holds only the background, the
// axes and the grey labels; the obstacles outside the lot are saturated colours.
TEST(FiguresTest, RenderedMarginsShowOnlyAxesAndLabels) {
  const Scenario s = outsideLot();
  const int w = 450;
  const int h = 300;
  const SceneStyle style = SceneStyle{}.scaled(styleScaleFor(h));
  RenderDef def;
  def.width_px = w;
  def.height_px = h;
  Renderer renderer(def);
  const Extent2 lot = lotOf(s);
  for (const char* name : {"lot_map", "cspace_slice"}) {
    const Scene scene = std::string(name) == "lot_map"
                            ? buildLotMapFigure(s, style)
                            : buildCSpaceSliceFigure(s, degToRad(-60.0), style);
    RgbImage image;
    renderer.render(scene, figureCamera(name), image);
    const Camera cam = renderer.camera(scene, figureCamera(name));
    const Eigen::Vector2d lo = *cam.project({lot.x_min, lot.y_max, 0.0});  // top-left pixel
    const Eigen::Vector2d hi = *cam.project({lot.x_max, lot.y_min, 0.0});
    const double pad = 3.0;  // half the widest line on the border, and anti-aliasing
    int coloured_inside = 0;
    int coloured_margin = 0;
    for (int y = 0; y < h; ++y) {
      for (int x = 0; x < w; ++x) {
        const std::uint8_t* px = &image.pixels[3 * (static_cast<std::size_t>(y) * w + x)];
        const int spread = std::max({px[0], px[1], px[2]}) - std::min({px[0], px[1], px[2]});
        const bool coloured = spread > 24;  // greys (background, axes, labels) are below 10
        const bool margin =
            x + 1 < lo.x() - pad || x > hi.x() + pad || y + 1 < lo.y() - pad || y > hi.y() + pad;
        if (coloured && margin) ++coloured_margin;
        if (coloured && !margin) ++coloured_inside;
      }
    }
    EXPECT_EQ(coloured_margin, 0) << name;
    EXPECT_GT(coloured_inside, 1000) << name;  // the obstacles inside and across the edge
  }
}

}  // namespace
}  // namespace parksim
