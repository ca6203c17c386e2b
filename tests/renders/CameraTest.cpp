#include "parksim/renders/scene/Camera.h"

#include <gtest/gtest.h>

namespace parksim {
namespace {

Scene sceneWithExtent(double w, double h) {
  Scene s;
  s.extent = {0.0, 0.0, w, h};
  return s;
}

TEST(CameraTest, TopDownFramesTheExtentWithSquarePixels) {
  const Scene scene = sceneWithExtent(2.0, 1.0);
  CameraDef def;
  def.fill = 1.0;
  const Camera cam = makeCamera(def, scene, 400, 400);
  // 2 m across 400 px: 200 px/m both ways, the 1 m high extent centred vertically.
  const auto lo = cam.project({0.0, 0.0, 0.0});
  const auto hi = cam.project({2.0, 1.0, 0.0});
  ASSERT_TRUE(lo && hi);
  EXPECT_NEAR(lo->x(), 0.0, 1e-9);
  EXPECT_NEAR(lo->y(), 300.0, 1e-9);  // y grows downwards
  EXPECT_NEAR(hi->x(), 400.0, 1e-9);
  EXPECT_NEAR(hi->y(), 100.0, 1e-9);
  // Height does not move a point in a top-down view.
  const auto raised = cam.project({2.0, 1.0, 0.3});
  EXPECT_NEAR((*raised - *hi).norm(), 0.0, 1e-9);
}

TEST(CameraTest, PerspectiveKeepsTheExtentInViewAndLooksAtItsCentre) {
  Scene scene = sceneWithExtent(1.8, 1.2);
  scene.extent_top_m = 0.3;
  CameraDef def;
  def.mode = CameraMode::kPerspective;
  const Camera cam = makeCamera(def, scene, 640, 480);
  EXPECT_TRUE(cam.perspective);
  for (double x : {0.0, 1.8}) {
    for (double y : {0.0, 1.2}) {
      for (double z : {0.0, 0.3}) {
        const auto p = cam.project({x, y, z});
        ASSERT_TRUE(p);
        EXPECT_GE(p->x(), 0.0);
        EXPECT_LE(p->x(), 640.0);
        EXPECT_GE(p->y(), 0.0);
        EXPECT_LE(p->y(), 480.0);
      }
    }
  }
  const auto c = cam.project({0.9, 0.6, 0.15});
  ASSERT_TRUE(c);
  EXPECT_NEAR(c->x(), 320.0, 1e-6);
  EXPECT_NEAR(c->y(), 240.0, 1e-6);
  // Behind the camera: no pixel.
  const Eigen::Vector3d behind = cam.eye + (cam.eye - Eigen::Vector3d(0.9, 0.6, 0.15));
  EXPECT_FALSE(cam.project(behind));
}

TEST(CameraTest, FollowCameraCentresTheFocus) {
  Scene scene = sceneWithExtent(1.8, 1.2);
  scene.focus = Eigen::Vector3d(0.3, 0.2, 0.0);
  CameraDef def;
  def.mode = CameraMode::kFollow;
  def.follow_distance_m = 0.5;
  const Camera cam = makeCamera(def, scene, 320, 240);
  const auto p = cam.project(*scene.focus);
  ASSERT_TRUE(p);
  EXPECT_NEAR(p->x(), 160.0, 1e-6);
  EXPECT_NEAR(p->y(), 120.0, 1e-6);
  EXPECT_NEAR((cam.eye - *scene.focus).norm(), 0.5, 1e-12);
}

}  // namespace
}  // namespace parksim
