// The shipped worlds must reproduce the study's lot (shared/reference/README.md) exactly.

#include <array>
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "parksim/core/geometry/Angle.h"
#include "parksim/core/model/Geometry.h"
#include "parksim/scenario/world/ScenarioReader.h"
#include "tests/support/TestPaths.h"

namespace parksim {
namespace {

// The study's table: lower-left corner, width, height, m.
struct StudyRect {
  const char* name;
  ObstacleKind kind;
  double x, y, w, h;
};

constexpr std::array<StudyRect, 11> kStudyTable = {{
    {"wall_1", ObstacleKind::kWall, 0.500, 0.800, 0.100, 0.400},
    {"wall_2", ObstacleKind::kWall, 0.500, 0.000, 0.100, 0.400},
    {"robot_3", ObstacleKind::kParkedRobot, 0.700, 0.000, 0.085, 0.080},
    {"robot_4", ObstacleKind::kParkedRobot, 1.000, 0.000, 0.085, 0.080},
    {"robot_5", ObstacleKind::kParkedRobot, 1.300, 0.000, 0.085, 0.080},
    {"robot_6", ObstacleKind::kParkedRobot, 1.600, 0.000, 0.085, 0.080},
    {"island_7", ObstacleKind::kIsland, 0.800, 0.600, 0.800, 0.100},
    {"robot_8", ObstacleKind::kParkedRobot, 0.700, 1.115, 0.080, 0.085},
    {"robot_9", ObstacleKind::kParkedRobot, 1.000, 1.115, 0.080, 0.085},
    {"robot_10", ObstacleKind::kParkedRobot, 1.300, 1.115, 0.080, 0.085},
    {"robot_11", ObstacleKind::kParkedRobot, 1.600, 1.115, 0.080, 0.085},
}};

constexpr double kTol = 1e-9;

std::string worldPath(const char* file) {
  return parksim::testing::sourceDir() + "/worlds/" + file;
}

const Obstacle* findObstacle(const Scenario& s, const std::string& name) {
  for (const Obstacle& o : s.obstacles) {
    if (o.name == name) return &o;
  }
  return nullptr;
}

// Every corner of the loaded box must be a corner of the study's rectangle. The rectangle's
// corners are millimetres apart, so four matches within kTol are four distinct corners.
void expectMatchesStudyTable(const Scenario& s) {
  ASSERT_EQ(s.obstacles.size(), kStudyTable.size());
  for (const StudyRect& r : kStudyTable) {
    SCOPED_TRACE(r.name);
    const Obstacle* o = findObstacle(s, r.name);
    ASSERT_NE(o, nullptr);
    EXPECT_EQ(o->kind, r.kind);
    const std::array<Eigen::Vector2d, 4> expected = {
        Eigen::Vector2d(r.x, r.y), Eigen::Vector2d(r.x + r.w, r.y),
        Eigen::Vector2d(r.x + r.w, r.y + r.h), Eigen::Vector2d(r.x, r.y + r.h)};
    std::array<bool, 4> matched = {false, false, false, false};
    for (const Eigen::Vector2d& c : o->box.corners()) {
      bool found = false;
      for (std::size_t i = 0; i < expected.size(); ++i) {
        if (!matched[i] && std::abs(c.x() - expected[i].x()) <= kTol &&
            std::abs(c.y() - expected[i].y()) <= kTol) {
          matched[i] = true;
          found = true;
          break;
        }
      }
      EXPECT_TRUE(found) << "corner (" << c.x() << ", " << c.y() << ") is not in the table";
    }
  }
}

void expectStudyLotAndStart(const Scenario& s) {
  EXPECT_EQ(s.lot.x_min_m, 0.0);
  EXPECT_EQ(s.lot.y_min_m, 0.0);
  EXPECT_EQ(s.lot.x_max_m, 1.8);
  EXPECT_EQ(s.lot.y_max_m, 1.2);
  EXPECT_EQ(s.start.x, 0.1);
  EXPECT_EQ(s.start.y, 0.1);
  EXPECT_NEAR(s.start.theta, kPi / 2, 1e-15);
}

TEST(StudyWorlds, HeadInReproducesTheStudy) {
  const Scenario s = loadScenario(worldPath("head_in.yaml"));
  EXPECT_EQ(s.name, "head_in");
  EXPECT_EQ(s.source_path, worldPath("head_in.yaml"));
  expectStudyLotAndStart(s);
  expectMatchesStudyTable(s);
  EXPECT_EQ(s.goal.pose.x, 1.5);
  EXPECT_EQ(s.goal.pose.y, 0.04);
  EXPECT_NEAR(s.goal.pose.theta, -kPi / 2, 1e-15);
  EXPECT_EQ(s.goal.position_tolerance_m, 0.001);
  EXPECT_NEAR(s.goal.heading_tolerance_rad, degToRad(0.5), 1e-15);
  EXPECT_FALSE(s.goal.either_heading);
}

TEST(StudyWorlds, ParallelReproducesTheStudy) {
  const Scenario s = loadScenario(worldPath("parallel.yaml"));
  EXPECT_EQ(s.name, "parallel");
  expectStudyLotAndStart(s);
  expectMatchesStudyTable(s);
  EXPECT_EQ(s.goal.pose.x, 1.2);
  EXPECT_EQ(s.goal.pose.y, 1.16);
  EXPECT_EQ(s.goal.pose.theta, 0.0);
  EXPECT_FALSE(s.goal.either_heading);
}

TEST(StudyWorlds, UseTheStudysRobotAndDefaultPhysics) {
  for (const char* file : {"head_in.yaml", "parallel.yaml"}) {
    SCOPED_TRACE(file);
    const Scenario s = loadScenario(worldPath(file));
    const RobotDef study;
    EXPECT_EQ(s.robot.length_m, study.length_m);
    EXPECT_EQ(s.robot.width_m, study.width_m);
    EXPECT_EQ(s.robot.front_overhang_m, study.front_overhang_m);
    EXPECT_EQ(s.robot.wheel_base_m, study.wheel_base_m);
    EXPECT_EQ(s.robot.wheel_radius_m, study.wheel_radius_m);
    EXPECT_EQ(s.physics.time_step_s, PhysicsDef{}.time_step_s);
    // Parked robots are as tall as the ego robot; other obstacles take the format's default.
    EXPECT_EQ(findObstacle(s, "robot_3")->height_m, study.height_m);
    EXPECT_EQ(findObstacle(s, "wall_1")->height_m, 0.1);
  }
}

}  // namespace
}  // namespace parksim
