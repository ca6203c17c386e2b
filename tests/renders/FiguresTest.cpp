#include "parksim/renders/Figures.h"

#include <gtest/gtest.h>

#include <set>

#include "RenderTestUtil.h"
#include "parksim/renders/CSpace.h"
#include "parksim/renders/PngEncoder.h"

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
    EXPECT_EQ(p.points, cspaceSlice(s.obstacles[slices].box, s.robot, theta));
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

}  // namespace
}  // namespace parksim
