#include "parksim/renders/gl/Renderer.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <vector>

#include "RenderTestUtil.h"
#include "parksim/core/io/Error.h"
#include "parksim/renders/film/FrameRecorder.h"
#include "parksim/renders/image/PngEncoder.h"
#include "parksim/renders/scene/SceneBuilder.h"

namespace parksim {
namespace {

using rendertest::testLot;

// One renderer for the whole suite: context creation costs milliseconds, and reusing it is
// what the recorder does too.
class RendererTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    RenderDef def;
    def.width_px = 640;
    def.height_px = 480;
    renderer_ = new Renderer(def);
  }
  static void TearDownTestSuite() {
    delete renderer_;
    renderer_ = nullptr;
  }
  void SetUp() override { renderer_->setSize(640, 480); }

  static Renderer* renderer_;
  Scenario lot_ = testLot();
  SceneStyle style_;
};

Renderer* RendererTest::renderer_ = nullptr;

Eigen::Vector2i pixelOf(const Camera& cam, const Eigen::Vector3d& world) {
  const auto p = cam.project(world);
  EXPECT_TRUE(p.has_value());
  return {static_cast<int>(std::floor(p->x())), static_cast<int>(std::floor(p->y()))};
}

// Every pixel within `radius` of `center` has exactly `color`.
void expectPatch(const RgbImage& img, const Eigen::Vector2i& center, int radius, Rgba8 color,
                 int tolerance = 0) {
  for (int dy = -radius; dy <= radius; ++dy) {
    for (int dx = -radius; dx <= radius; ++dx) {
      const Rgba8 c = img.at(center.x() + dx, center.y() + dy);
      EXPECT_NEAR(c.r, color.r, tolerance) << "at " << center.x() + dx << "," << center.y() + dy;
      EXPECT_NEAR(c.g, color.g, tolerance) << "at " << center.x() + dx << "," << center.y() + dy;
      EXPECT_NEAR(c.b, color.b, tolerance) << "at " << center.x() + dx << "," << center.y() + dy;
    }
  }
}

TEST_F(RendererTest, ImageHasTheRequestedSize) {
  RgbImage img;
  const Scene scene = buildLotScene(lot_, style_);
  renderer_->render(scene, {}, img);
  EXPECT_EQ(img.width, 640);
  EXPECT_EQ(img.height, 480);
  EXPECT_EQ(img.pixels.size(), 640u * 480u * 3u);
  renderer_->setSize(321, 123);
  renderer_->render(scene, {}, img);
  EXPECT_EQ(img.width, 321);
  EXPECT_EQ(img.height, 123);
  EXPECT_EQ(img.pixels.size(), 321u * 123u * 3u);
}

TEST_F(RendererTest, UsesMultisamplingAndDescribesTheContext) {
  EXPECT_EQ(renderer_->samples(), 4);
  const std::string name = renderer_->backend() == ContextBackend::kEgl ? "EGL" : "OSMesa";
  EXPECT_EQ(renderer_->description().rfind(name, 0), 0u) << renderer_->description();
  EXPECT_NE(renderer_->description().find("Core Profile"), std::string::npos);
}

TEST_F(RendererTest, TopViewShowsRobotAndObstaclesInTheirColours) {
  const Pose2 pose{0.3, 0.5, degToRad(30.0)};
  ViewState view;
  view.robot = pose;
  const Scene scene = buildScene(lot_, view, style_);
  RgbImage img;
  renderer_->render(scene, {}, img);
  const Camera cam = renderer_->camera(scene, {});

  const OrientedBox body = footprintAt(lot_.robot, pose);
  const Eigen::Vector3d top(body.center.x(), body.center.y(), lot_.robot.height_m);
  expectPatch(img, pixelOf(cam, top), 3, style_.robot);

  for (const Obstacle& o : lot_.obstacles) {
    const Eigen::Vector3d c(o.box.center.x(), o.box.center.y(), o.height_m);
    expectPatch(img, pixelOf(cam, c), 2, style_.colorFor(o.kind));
  }
  // Open ground between grid lines, and outside the lot.
  expectPatch(img, pixelOf(cam, {1.05, 0.35, 0.0}), 2, style_.lot);
  expectPatch(img, pixelOf(cam, {lot_.lot.x_max_m + 0.02, 0.5, 0.0}), 1, style_.background);
}

TEST_F(RendererTest, PerspectiveViewShowsTheRobotsTopInItsColour) {
  const Pose2 pose{1.0, 0.4, 0.0};
  ViewState view;
  view.robot = pose;
  const Scene scene = buildScene(lot_, view, style_);
  for (CameraMode mode : {CameraMode::kPerspective, CameraMode::kFollow}) {
    CameraDef def;
    def.mode = mode;
    RgbImage img;
    renderer_->render(scene, def, img);
    const Camera cam = renderer_->camera(scene, def);
    const OrientedBox body = footprintAt(lot_.robot, pose);
    const Eigen::Vector3d top(body.center.x(), body.center.y(), lot_.robot.height_m);
    // Upward faces keep their colour under the light; allow rounding of the lighting factor.
    expectPatch(img, pixelOf(cam, top), mode == CameraMode::kFollow ? 4 : 1, style_.robot, 2);
  }
}

TEST_F(RendererTest, FramesChangeAsTheRobotMoves) {
  ViewState view;
  view.robot = Pose2{0.3, 0.5, 0.0};
  const Scene before = buildScene(lot_, view, style_);
  view.robot = Pose2{0.3, 0.7, 0.0};
  const Scene after = buildScene(lot_, view, style_);
  RgbImage a;
  RgbImage b;
  renderer_->render(before, {}, a);
  renderer_->render(after, {}, b);
  EXPECT_NE(a, b);
  const Camera cam = renderer_->camera(before, {});
  const OrientedBox old_body = footprintAt(lot_.robot, Pose2{0.3, 0.5, 0.0});
  const Eigen::Vector2i old_px =
      pixelOf(cam, {old_body.center.x(), old_body.center.y(), lot_.robot.height_m});
  expectPatch(a, old_px, 2, style_.robot);
  EXPECT_NE(b.at(old_px.x(), old_px.y()), style_.robot);
}

// A film's view: the lot and plan behind, the robot and its driven path in front, and an
// overlay; `obstacle_shift` pushes the first obstacle along x, m.
SceneLayers filmLayers(const Scenario& lot, const SceneStyle& style, const Pose2& robot,
                       double obstacle_shift = 0.0) {
  static const std::vector<Pose2> planned = {
      {0.2, 0.3, 0.0}, {0.5, 0.45, 0.3}, {0.9, 0.5, 0.0}, {1.3, 0.45, -0.3}};
  std::vector<Pose2> executed = {{0.2, 0.3, 0.0}, {0.3, 0.35, 0.2}, robot};
  std::vector<Pose2> obstacles;
  for (const Obstacle& o : lot.obstacles) {
    obstacles.push_back({o.box.center.x(), o.box.center.y(), o.box.yaw});
  }
  obstacles.front().x += obstacle_shift;
  ViewState view = rendertest::drivingView(
      planned, executed, {robot.x + 0.01, robot.y, robot.theta}, {"film", 1.25, 0.001, 0.01});
  view.obstacle_poses = obstacles;
  return buildSceneLayers(lot, view, style);
}

RgbImage renderLayers(Renderer& renderer, const SceneLayers& layers) {
  RgbaImage img(renderer.width(), renderer.height());
  renderer.renderInto(layers.back, layers.front, {}, img, 0);
  return img.rgb();
}

// The kept backdrop is an optimisation only: whatever the renderer drew before, a film's frame
// has the bytes a fresh renderer gives it. Frames use one sample; figures may use four.
TEST_F(RendererTest, AKeptBackdropGivesTheImageOfAFreshOne) {
  for (int samples : {1, 4}) {
    SCOPED_TRACE(samples);
    RenderDef def;
    def.msaa_samples = samples;
    Renderer renderer(def);
    const SceneLayers a = filmLayers(lot_, style_, {0.35, 0.4, 0.3});
    const SceneLayers b = filmLayers(lot_, style_, {0.45, 0.45, 0.2});
    const SceneLayers pushed = filmLayers(lot_, style_, {0.45, 0.45, 0.2}, 0.05);
    ASSERT_EQ(a.back, b.back);
    ASSERT_NE(b.back, pushed.back);

    const RgbImage a1 = renderLayers(renderer, a);
    const RgbImage b1 = renderLayers(renderer, b);  // a's backdrop, copied back
    EXPECT_EQ(renderer.backdropsDrawn(), 1);
    RgbImage whole;
    renderer.render(buildScene(lot_, {}, style_), FrameDef{}.camera_3d, whole);  // as both views
    const RgbImage b2 = renderLayers(renderer, b);
    EXPECT_EQ(renderer.backdropsDrawn(), 1);
    const RgbImage pushed1 = renderLayers(renderer, pushed);
    const RgbImage a2 = renderLayers(renderer, a);
    EXPECT_EQ(renderer.backdropsDrawn(), 3);
    RgbaImage framed(640, 480);  // the same backdrop through another camera: drawn anew
    renderer.renderInto(a.back, a.front, {.fill = 0.8}, framed, 0);
    EXPECT_EQ(renderer.backdropsDrawn(), 4);
    renderer.setSize(320, 240);
    const RgbImage small = renderLayers(renderer, a);

    EXPECT_NE(a1, b1);
    EXPECT_EQ(b2, b1);
    EXPECT_NE(b1, pushed1);
    EXPECT_EQ(a2, a1);
    Renderer fresh(def);
    EXPECT_EQ(renderLayers(fresh, b), b1);
    EXPECT_EQ(renderLayers(fresh, pushed), pushed1);
    RgbaImage fresh_framed(640, 480);
    fresh.renderInto(a.back, a.front, {.fill = 0.8}, fresh_framed, 0);
    EXPECT_EQ(fresh_framed.rgb(), framed.rgb());
    fresh.setSize(320, 240);
    EXPECT_EQ(renderLayers(fresh, a), small);

    // The pushed obstacle shows where it went, not where the kept backdrop had it.
    renderer.setSize(640, 480);
    const Obstacle& first = lot_.obstacles.front();
    ASSERT_EQ(first.box.yaw, 0.0);  // its right side is along y
    const Eigen::Vector3d moved(first.box.center.x() + 0.05 + first.box.half_extents.x() - 0.01,
                                first.box.center.y(), first.height_m);
    expectPatch(pushed1, pixelOf(renderer.camera(pushed.front, {}), moved), 1,
                style_.colorFor(first.kind));
  }
}

// Columns [x0, x0 + width) of `img`, without alpha.
RgbImage columnsOf(const RgbaImage& img, int x0, int width) {
  RgbImage out(width, img.height);
  for (int y = 0; y < img.height; ++y) {
    rgbaToRgb(&img.pixels[(static_cast<std::size_t>(y) * img.width + x0) * 4],
              &out.pixels[static_cast<std::size_t>(y) * width * 3],
              static_cast<std::size_t>(width));
  }
  return out;
}

// A film drawn by renderChanges into the right half of a wide image, with its rows gathered
// as an encoder does, is the film drawn whole: as the robot drives (its driven path growing,
// the overlay's time and errors changing), when a frame repeats, after an obstacle was pushed,
// after another scene was drawn in between and after a resize. The image renderChanges draws
// into is noise before each call, so nothing depends on rows it did not return.
TEST_F(RendererTest, ChangedRowsGiveTheImageOfAWholeDraw) {
  for (int samples : {1, 4}) {
    SCOPED_TRACE(samples);
    RenderDef def;
    def.msaa_samples = samples;
    def.width_px = 320;
    def.height_px = 240;
    Renderer changes(def);
    Renderer whole(def);
    const std::vector<Pose2> planned = {{0.1, 0.1, 1.57}, {0.6, 0.6, 0.0}, {1.4, 0.3, -1.0}};
    std::vector<Pose2> executed = {{0.1, 0.1, 1.57}};
    RgbaImage kept(640, 240);  // the film's frame as its encoder holds it; the view on the right
    const std::size_t row_bytes = 640 * 4;
    std::uint32_t noise = 99;
    long rows_read = 0;
    for (int k = 1; k <= 24; ++k) {
      SCOPED_TRACE(k);
      const double s = 0.04 * k;
      executed.push_back({0.1 + s, 0.1 + 0.5 * s, 1.57 - 0.05 * k});
      ViewState view = rendertest::drivingView(planned, executed, executed.back(),
                                               {"film", 0.1 * k, 0.001 * k, 0.01 * (k % 5)});
      std::vector<Pose2> obstacles;
      for (const Obstacle& o : lot_.obstacles) {
        obstacles.push_back({o.box.center.x(), o.box.center.y(), o.box.yaw});
      }
      if (k >= 12) obstacles.front().x += 0.05;  // pushed: a new backdrop
      view.obstacle_poses = obstacles;
      const SceneLayers layers = buildSceneLayers(lot_, view, style_);
      if (k == 18) {  // something else drawn: nothing to build on
        RgbImage other;
        changes.render(buildScene(lot_, {}, style_), FrameDef{}.camera_3d, other);
      }
      if (k == 20) {  // new framebuffers
        changes.setSize(160, 120);
        changes.setSize(320, 240);
      }

      RgbaImage scratch(640, 240);
      for (std::uint8_t& b : scratch.pixels) {
        noise = noise * 1664525u + 1013904223u;
        b = static_cast<std::uint8_t>(noise >> 24);
      }
      const std::vector<RowSpan> rows =
          changes.renderChanges(layers.back, layers.front, {}, scratch, 320);
      int previous_end = -1;
      int step_rows = 0;
      for (const RowSpan& r : rows) {
        ASSERT_LT(previous_end, r.begin);  // sorted and apart
        ASSERT_LT(r.begin, r.end);
        ASSERT_LE(r.end, 240);
        previous_end = r.end;
        std::copy_n(scratch.pixels.begin() + static_cast<std::ptrdiff_t>(r.begin * row_bytes),
                    static_cast<std::size_t>(r.end - r.begin) * row_bytes,
                    kept.pixels.begin() + static_cast<std::ptrdiff_t>(r.begin * row_bytes));
        step_rows += r.end - r.begin;
      }
      rows_read += step_rows;
      if (k == 1 || k == 12 || k == 18 || k == 20) {
        EXPECT_EQ(rows, (std::vector<RowSpan>{{0, 240}}));
      } else {
        EXPECT_GT(step_rows, 0);
        EXPECT_LT(step_rows, 180) << "a step changes some rows, not all";
      }
      RgbaImage expected(320, 240);
      whole.renderInto(layers.back, layers.front, {}, expected, 0);
      ASSERT_EQ(columnsOf(kept, 320, 320), expected.rgb());
      if (k == 6) {  // the same frame again (a sparse caller): nothing to read
        EXPECT_TRUE(changes.renderChanges(layers.back, layers.front, {}, scratch, 320).empty());
      }
    }
    EXPECT_LT(rows_read, 24 * 240 / 2);
  }
}

// The front is drawn over the backdrop as it is: its first polygon, though a rectangle like
// the lot's, is drawn (not left to a clear that never comes); a front framed apart is refused.
TEST_F(RendererTest, TheFrontIsDrawnWholeOverItsOwnBackdrop) {
  SceneLayers layers = filmLayers(lot_, style_, {0.35, 0.4, 0.3});
  const Rgba8 patch{250, 0, 250, 255};
  layers.front.polygons.insert(
      layers.front.polygons.begin(),
      ScenePolygon{{{1.0, 0.3}, {1.1, 0.3}, {1.1, 0.4}, {1.0, 0.4}}, 0.0009, patch});
  RenderDef def;
  def.msaa_samples = 1;
  Renderer renderer(def);
  const RgbImage img = renderLayers(renderer, layers);
  expectPatch(img, pixelOf(renderer.camera(layers.front, {}), {1.05, 0.35, 0.0}), 3, patch);

  layers.front.extent.x_max += 0.1;
  RgbaImage out(640, 480);
  EXPECT_THROW(renderer.renderInto(layers.back, layers.front, {}, out, 0), Error);
}

// Drawing the backdrop first and the front over it is the whole scene's picture but for the
// order at a few soft edges: colours of every item are exact and at most a few pixels differ.
TEST_F(RendererTest, BackdropAndFrontDrawTheWholeScenesPicture) {
  RenderDef def;
  def.msaa_samples = 1;
  Renderer renderer(def);
  const Pose2 pose{0.35, 0.4, 0.3};
  const SceneLayers layers = filmLayers(lot_, style_, pose);
  Scene whole = layers.back;
  appendScene(whole, layers.front);
  RgbImage one;
  renderer.render(whole, {}, one);
  const RgbImage two = renderLayers(renderer, layers);
  int differ = 0;
  for (std::size_t i = 0; i < one.pixels.size(); i += 3) {
    differ += one.pixels[i] != two.pixels[i] || one.pixels[i + 1] != two.pixels[i + 1] ||
              one.pixels[i + 2] != two.pixels[i + 2];
  }
  EXPECT_LT(differ, 30) << "of 307200 pixels";
  const Camera cam = renderer.camera(layers.front, {});
  const OrientedBox body = footprintAt(lot_.robot, pose);
  expectPatch(two, pixelOf(cam, {body.center.x(), body.center.y(), lot_.robot.height_m}), 3,
              style_.robot);
  for (const Obstacle& o : lot_.obstacles) {
    const Eigen::Vector3d c(o.box.center.x(), o.box.center.y(), o.height_m);
    expectPatch(two, pixelOf(cam, c), 2, style_.colorFor(o.kind));
  }
}

TEST_F(RendererTest, SameSceneGivesTheSameImage) {
  ViewState view;
  view.robot = Pose2{0.8, 0.3, 1.0};
  const Scene scene = buildScene(lot_, view, style_);
  RgbImage a;
  RgbImage b;
  renderer_->render(scene, {}, a);
  renderer_->render(scene, {CameraMode::kFollow}, b);
  renderer_->render(scene, {}, b);
  EXPECT_EQ(a, b);
}

TEST_F(RendererTest, DrawsText) {
  Scene scene;
  scene.extent = {0, 0, 1, 1};
  scene.texts.push_back({"parksim 123",
                         std::nullopt,
                         {10, 10},
                         20.0f,
                         rgb(0, 0, 0),
                         {0, 0, 0, 0},
                         HAlign::kLeft,
                         VAlign::kTop});
  RgbImage img;
  renderer_->render(scene, {}, img);
  int dark = 0;
  for (int y = 10; y < 34; ++y) {
    for (int x = 10; x < 150; ++x) dark += img.at(x, y).r < 128 ? 1 : 0;
  }
  EXPECT_GT(dark, 100);
  // Nothing below the line of text.
  for (int x = 0; x < 640; ++x) EXPECT_EQ(img.at(x, 200), scene.background);
}

TEST_F(RendererTest, ViewsGoSideBySide) {
  ViewState view;
  view.robot = Pose2{0.8, 0.3, 1.0};
  const Scene scene = buildScene(lot_, view, style_);
  RgbImage single;
  renderer_->render(scene, {}, single);
  RgbImage follow;
  renderer_->render(scene, {CameraMode::kFollow}, follow);
  RgbaImage wide_rgba(1280, 480);
  renderer_->renderInto(scene, {CameraMode::kFollow}, wide_rgba, 640);
  renderer_->renderInto(scene, {}, wide_rgba, 0);
  const RgbImage wide = wide_rgba.rgb();
  for (int y = 0; y < 480; ++y) {
    for (int x = 0; x < 640; ++x) {
      ASSERT_EQ(wide.at(x, y), single.at(x, y));
      ASSERT_EQ(wide.at(640 + x, y), follow.at(x, y));
    }
  }
  EXPECT_THROW(renderer_->renderInto(scene, {}, wide_rgba, 700), Error);
  RgbaImage short_rgba(1280, 479);
  EXPECT_THROW(renderer_->renderInto(scene, {}, short_rgba, 0), Error);
}

TEST_F(RendererTest, SavesAPictureForHumans) {
  // Not an assertion: a picture to look at when changing the renderer.
  ViewState view;
  view.robot = Pose2{0.3, 0.5, degToRad(30.0)};
  view.reference = Pose2{0.32, 0.52, degToRad(35.0)};
  view.overlay = Overlay{"test_lot", 1.25, 0.0123, degToRad(1.5)};
  const Scene scene = buildScene(lot_, view, style_);
  RgbImage img;
  const std::string dir = rendertest::outputDir("RendererTest");
  renderer_->render(scene, {}, img);
  writePng(dir + "/top.png", img);
  renderer_->render(scene, {CameraMode::kFollow}, img);
  writePng(dir + "/follow.png", img);
  renderer_->render(scene, {CameraMode::kPerspective}, img);
  writePng(dir + "/perspective.png", img);
}

}  // namespace
}  // namespace parksim

namespace parksim {
namespace {

TEST(RendererWithoutMsaaTest, GroundClearDrawsWhatThePolygonWould) {
  RenderDef def;
  def.msaa_samples = 1;
  Renderer renderer(def);
  EXPECT_EQ(renderer.samples(), 1);
  const Scenario lot = rendertest::testLot();
  const SceneStyle style;
  ViewState view;
  view.robot = Pose2{0.7, 0.45, 0.3};
  const Scene fast = buildScene(lot, view, style);
  // The same rectangle with a fifth, collinear point is drawn as triangles instead.
  Scene slow = fast;
  ScenePolygon& ground = slow.polygons.front();
  ground.points.insert(ground.points.begin() + 1, 0.5 * (ground.points[0] + ground.points[1]));
  RgbImage a;
  RgbImage b;
  renderer.render(fast, {}, a);
  renderer.render(slow, {}, b);
  EXPECT_EQ(a, b);
  // Edge smoothing leaves the inside of faces alone.
  const Camera cam = renderer.camera(fast, {});
  const OrientedBox body = footprintAt(lot.robot, *view.robot);
  const auto p = cam.project({body.center.x(), body.center.y(), lot.robot.height_m});
  ASSERT_TRUE(p);
  EXPECT_EQ(a.at(static_cast<int>(p->x()), static_cast<int>(p->y())), style.robot);
}

}  // namespace
}  // namespace parksim
