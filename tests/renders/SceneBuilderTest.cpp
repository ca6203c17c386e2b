#include "parksim/renders/scene/SceneBuilder.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "RenderTestUtil.h"

namespace parksim {
namespace {

using rendertest::drivingView;
using rendertest::testLot;

TEST(SceneBuilderTest, LotSceneHasOneBoxPerObstacleInItsKindsColour) {
  const Scenario s = testLot();
  const SceneStyle style;
  const Scene scene = buildLotScene(s, style);
  ASSERT_EQ(scene.boxes.size(), s.obstacles.size());
  for (std::size_t i = 0; i < s.obstacles.size(); ++i) {
    EXPECT_EQ(scene.boxes[i].color, style.colorFor(s.obstacles[i].kind));
    EXPECT_EQ(scene.boxes[i].footprint.center, s.obstacles[i].box.center);
    EXPECT_DOUBLE_EQ(scene.boxes[i].height_m, s.obstacles[i].height_m);
  }
  EXPECT_LE(scene.extent.x_min, s.lot.x_min_m - style.margin_m);
  EXPECT_GE(scene.extent.x_max, s.lot.x_max_m + style.margin_m);
  ASSERT_EQ(scene.arrows.size(), 2u);
  EXPECT_EQ(scene.arrows[0].pose, s.start);
  EXPECT_EQ(scene.arrows[0].color, style.start);
  EXPECT_EQ(scene.arrows[1].pose, s.goal.pose);
  EXPECT_EQ(scene.arrows[1].color, style.goal);
  EXPECT_FALSE(scene.focus);
  EXPECT_TRUE(scene.texts.empty());
}

TEST(SceneBuilderTest, ObstaclesMoveAndTurnRedOnContact) {
  const Scenario s = testLot();
  const SceneStyle style;
  std::vector<Pose2> poses;
  for (const Obstacle& o : s.obstacles)
    poses.push_back({o.box.center.x(), o.box.center.y(), o.box.yaw});
  poses.back() = {1.35, 0.05, 0.3};  // the parked robot was pushed
  const std::vector<int> contacts = {3};
  const Scene scene = buildLotScene(s, style, poses, contacts);
  EXPECT_EQ(scene.boxes.back().footprint.center, Eigen::Vector2d(1.35, 0.05));
  EXPECT_DOUBLE_EQ(scene.boxes.back().footprint.yaw, 0.3);
  EXPECT_EQ(scene.boxes.back().color, style.contact);
  EXPECT_EQ(scene.boxes.front().color, style.wall);
}

TEST(SceneBuilderTest, ViewStateAddsRobotPathsAndOverlay) {
  const Scenario s = testLot();
  const SceneStyle style;
  const std::vector<Pose2> planned = {{0.1, 0.1, 0.0}, {0.2, 0.1, 0.0}, {0.3, 0.2, 0.5}};
  const std::vector<Pose2> executed = {{0.1, 0.1, 0.0}, {0.15, 0.1, 0.0}};
  ViewState view = drivingView(planned, executed, {0.16, 0.1, 0.0}, {"lot", 2.5, 0.004, 0.01});
  const Scene lot = buildLotScene(s, style);
  const Scene scene = buildScene(s, view, style);
  // Body and two wheels.
  ASSERT_EQ(scene.boxes.size(), lot.boxes.size() + 3);
  EXPECT_EQ(scene.boxes[lot.boxes.size()].color, style.robot);
  EXPECT_EQ(scene.boxes[lot.boxes.size()].footprint.center,
            footprintAt(s.robot, *view.robot).center);
  ASSERT_TRUE(scene.focus);
  EXPECT_DOUBLE_EQ(scene.focus->x(), 0.15);
  // Planned and executed paths and the reference outline, in their colours.
  int planned_lines = 0;
  int executed_lines = 0;
  int reference_lines = 0;
  for (const ScenePolyline& l : scene.lines) {
    planned_lines += l.color == style.planned && l.points.size() == 3;
    executed_lines += l.color == style.executed && l.points.size() == 2;
    reference_lines += l.color == style.reference && l.closed;
  }
  EXPECT_EQ(planned_lines, 1);
  EXPECT_EQ(executed_lines, 1);
  EXPECT_EQ(reference_lines, 1);
  ASSERT_EQ(scene.texts.size(), 2u);
  EXPECT_NE(scene.texts[0].text.find("t =   2.50 s"), std::string::npos) << scene.texts[0].text;
  EXPECT_NE(scene.texts[1].text.find("4.00 mm"), std::string::npos) << scene.texts[1].text;
  EXPECT_FALSE(scene.texts[0].world);
}

// A car (issue 38): four wheels, the front pair axle_distance ahead and turned by their
// Ackermann angles of the steering: both axles' normals meet at the turn's centre.
TEST(SceneBuilderTest, ACarsFrontWheelsAreDrawnTurned) {
  Scenario s = testLot();
  s.robot = midSizeCar();
  s.lot = {0.0, 0.0, 50.0, 50.0};
  const SceneStyle style;
  ViewState view;
  view.robot = Pose2{20.0, 20.0, 0.3};
  view.robot_steer_rad = 0.5;
  const Scene lot = buildLotScene(s, style);
  const Scene scene = buildScene(s, view, style);
  ASSERT_EQ(scene.boxes.size(), lot.boxes.size() + 5);  // body and four wheels
  const double turn_radius = s.robot.axle_distance_m / std::tan(0.5);
  const Eigen::Vector2d centre(20.0 - turn_radius * std::sin(0.3),
                               20.0 + turn_radius * std::cos(0.3));
  for (std::size_t i = lot.boxes.size() + 1; i < scene.boxes.size(); ++i) {
    const OrientedBox& wheel = scene.boxes[i].footprint;
    EXPECT_EQ(scene.boxes[i].color, style.wheel);
    // Each wheel's axle (its lateral axis) points at the centre.
    const Eigen::Vector2d to_centre = (centre - wheel.center).normalized();
    const Eigen::Vector2d heading(std::cos(wheel.yaw), std::sin(wheel.yaw));
    EXPECT_NEAR(heading.dot(to_centre), 0.0, 1e-12) << i;
  }
  // The front wheels turned, the rear ones not.
  EXPECT_DOUBLE_EQ(scene.boxes[lot.boxes.size() + 1].footprint.yaw, 0.3);
  EXPECT_GT(scene.boxes[lot.boxes.size() + 3].footprint.yaw, 0.3 + 0.4);
  // Seen from above the wheels lie under the body (track 1.6 m, width 1.942 m): each is drawn
  // again on the roof, its four corners the wheel's own, so a top view shows the steering.
  std::vector<const ScenePolygon*> on_roof;
  for (const ScenePolygon& p : scene.polygons) {
    if (p.color == style.wheel) on_roof.push_back(&p);
  }
  ASSERT_EQ(on_roof.size(), 4u);
  for (std::size_t k = 0; k < 4; ++k) {
    const OrientedBox& wheel = scene.boxes[lot.boxes.size() + 1 + k].footprint;
    EXPECT_GT(on_roof[k]->z_m, s.robot.height_m);
    ASSERT_EQ(on_roof[k]->points.size(), 4u);
    // The corners from the wheel's centre, half-extents and yaw, computed here.
    const Eigen::Vector2d along(std::cos(wheel.yaw), std::sin(wheel.yaw));
    const Eigen::Vector2d across(-along.y(), along.x());
    for (const double u : {-1.0, 1.0}) {
      for (const double v : {-1.0, 1.0}) {
        const Eigen::Vector2d corner =
            wheel.center + u * wheel.half_extents.x() * along + v * wheel.half_extents.y() * across;
        double nearest = 1e9;
        for (const Eigen::Vector2d& q : on_roof[k]->points) {
          nearest = std::min(nearest, (q - corner).norm());
        }
        EXPECT_LT(nearest, 1e-12) << k;
      }
    }
  }
}

// A film keeps the back layer while the robot drives: it must change with the obstacles and
// with nothing that moves with the robot, and the two layers must make buildScene's scene.
TEST(SceneBuilderTest, LayersSplitWhatStaysFromWhatMoves) {
  const Scenario s = testLot();
  const SceneStyle style;
  const std::vector<Pose2> planned = {{0.1, 0.1, 0.0}, {0.2, 0.1, 0.0}, {0.3, 0.2, 0.5}};
  std::vector<Pose2> executed = {{0.1, 0.1, 0.0}, {0.15, 0.1, 0.0}};
  ViewState view = drivingView(planned, executed, {0.16, 0.1, 0.0}, {"lot", 2.5, 0.004, 0.01});
  const SceneLayers first = buildSceneLayers(s, view, style);
  Scene whole = first.back;
  appendScene(whole, first.front);
  EXPECT_EQ(whole, buildScene(s, view, style));
  EXPECT_EQ(first.front.extent, first.back.extent);
  EXPECT_TRUE(first.back.texts.empty());
  EXPECT_EQ(first.front.arrows.size(), 2u);  // start and goal, over the driven path

  // The robot drives on, the overlay ticks: only the front changes.
  executed.push_back({0.2, 0.12, 0.1});
  view.executed_path = executed;  // the vector moved
  view.robot = executed.back();
  view.reference = Pose2{0.21, 0.12, 0.1};
  view.overlay->time_s = 2.6;
  const SceneLayers later = buildSceneLayers(s, view, style);
  EXPECT_EQ(later.back, first.back);
  EXPECT_NE(later.front, first.front);

  // A touched obstacle turns red, a pushed one moves: the back changes.
  const std::vector<int> touching = {0};
  view.contacts = touching;
  EXPECT_NE(buildSceneLayers(s, view, style).back, first.back);
  view.contacts = {};
  std::vector<Pose2> poses;
  for (const Obstacle& o : s.obstacles)
    poses.push_back({o.box.center.x(), o.box.center.y(), o.box.yaw});
  view.obstacle_poses = poses;
  EXPECT_EQ(buildSceneLayers(s, view, style).back, first.back);
  poses.front().y += 0.01;
  EXPECT_NE(buildSceneLayers(s, view, style).back, first.back);
}

TEST(SceneBuilderTest, SampledPathFollowsTheTrajectorysArcs) {
  const RobotDef robot;
  const Trajectory traj = rendertest::sampleDrive(robot, {0.1, 0.1, kPi / 2});
  const std::vector<Pose2> path = samplePath(traj, robot, 0.002, 0.05);
  ASSERT_GT(path.size(), traj.points.size());
  EXPECT_EQ(path.front(), traj.points.front().pose);
  EXPECT_EQ(path.back(), traj.points.back().pose);
  for (std::size_t i = 1; i < path.size(); ++i) {
    EXPECT_LE(positionDistance(path[i - 1], path[i]), 0.002 + 1e-12);
    EXPECT_LE(headingDistance(path[i - 1], path[i]), 0.05 + 1e-12);
  }
  EXPECT_TRUE(samplePath(Trajectory{}, robot).empty());
}

TEST(SceneBuilderTest, RoundAndPolygonalObstaclesArePrisms) {
  Scenario s;
  s.obstacles = {Obstacle::makeCircle("c", ObstacleKind::kBollard, {{0.5, 0.5}, 0.03}, 0.12),
                 Obstacle::makePolygon("p", ObstacleKind::kIsland,
                                       {{0.9, 0.4}, {1.2, 0.45}, {1.1, 0.7}}, 0.05)};
  const SceneStyle style;
  const Scene scene = buildLotScene(s, style);
  EXPECT_TRUE(scene.boxes.empty());
  ASSERT_EQ(scene.prisms.size(), 2u);
  EXPECT_EQ(scene.prisms[0].footprint.size(), static_cast<std::size_t>(style.circle_segments));
  for (const Eigen::Vector2d& p : scene.prisms[0].footprint) {
    EXPECT_NEAR((p - Eigen::Vector2d(0.5, 0.5)).norm(), 0.03, 1e-12);
  }
  EXPECT_EQ(scene.prisms[0].height_m, 0.12);
  EXPECT_EQ(scene.prisms[0].color, style.bollard);
  EXPECT_EQ(scene.prisms[1].footprint, s.obstacles[1].vertices);
  // Moved by the simulation (bounding-box centre and yaw): the outline moves with it.
  const std::vector<Pose2> poses{
      {0.5, 0.5, 0.0},
      {s.obstacles[1].box.center.x() + 0.1, s.obstacles[1].box.center.y(), kPi / 2}};
  const std::vector<int> contacts{1};
  const Scene moved = buildLotScene(s, style, poses, contacts);
  const Eigen::Vector2d c = s.obstacles[1].box.center;
  const Eigen::Vector2d d = s.obstacles[1].vertices[0] - c;
  EXPECT_NEAR((moved.prisms[1].footprint[0] - (c + Eigen::Vector2d(0.1 - d.y(), d.x()))).norm(),
              0.0, 1e-12);
  EXPECT_EQ(moved.prisms[1].color, style.contact);
}

}  // namespace
}  // namespace parksim
