#include "parksim/scenario/world/ScenarioReader.h"

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <string_view>

#include <gtest/gtest.h>

#include "parksim/core/geometry/Angle.h"
#include "parksim/core/io/Error.h"
#include "parksim/core/model/Geometry.h"
#include "tests/support/TestPaths.h"

namespace parksim {
// Named, not anonymous: its program is compiled as one unity batch, where another file's
// helpers of the same names would meet these.
namespace scenario_reader_test {

// Lines 1-3 of most test documents; a 2 m x 2 m lot.
constexpr std::string_view kHead =
    "format: parksim-world/1\n"
    "name: t\n"
    "lot: {x_min: 0, y_min: 0, x_max: 2, y_max: 2}\n";
// Lines 4-5 after kHead.
constexpr std::string_view kStartGoal =
    "start: [0.5, 0.5, 0]\n"
    "goal: {pose: [1.5, 1.5, 90]}\n";

std::string valid(std::string_view extra = "") {
  return std::string(kHead) + std::string(kStartGoal) + std::string(extra);
}

std::string errorOf(std::string_view yaml) {
  try {
    parseScenario(yaml, "t.yaml");
  } catch (const Error& e) {
    return e.what();
  }
  return "(accepted)";
}

// ---- Accepted input and defaults -------------------------------------------------------------

TEST(ScenarioReader, MinimalFileGetsEveryDefault) {
  const Scenario s = parseScenario(valid(), "mem.yaml");
  EXPECT_EQ(s.name, "t");
  EXPECT_EQ(s.source_path, "mem.yaml");
  EXPECT_EQ(s.lot.x_max_m, 2.0);
  EXPECT_TRUE(s.obstacles.empty());
  EXPECT_EQ(s.start, (Pose2{0.5, 0.5, 0.0}));
  EXPECT_EQ(s.goal.pose.x, 1.5);
  EXPECT_EQ(s.goal.pose.theta, degToRad(90.0));
  EXPECT_EQ(s.goal.position_tolerance_m, 0.001);
  EXPECT_EQ(s.goal.heading_tolerance_rad, degToRad(0.5));
  EXPECT_FALSE(s.goal.either_heading);

  const RobotDef r;
  EXPECT_EQ(s.robot.length_m, r.length_m);
  EXPECT_EQ(s.robot.width_m, r.width_m);
  EXPECT_EQ(s.robot.front_overhang_m, r.front_overhang_m);
  EXPECT_EQ(s.robot.wheel_base_m, r.wheel_base_m);
  EXPECT_EQ(s.robot.wheel_radius_m, r.wheel_radius_m);
  EXPECT_EQ(s.robot.max_wheel_speed_radps, r.max_wheel_speed_radps);
  EXPECT_EQ(s.robot.max_wheel_accel_radps2, r.max_wheel_accel_radps2);
  EXPECT_EQ(s.robot.height_m, r.height_m);

  const PhysicsDef p;
  EXPECT_EQ(s.physics.time_step_s, p.time_step_s);
  EXPECT_EQ(s.physics.solver_iterations, p.solver_iterations);
  EXPECT_EQ(s.physics.gravity_mps2, p.gravity_mps2);
  EXPECT_EQ(s.physics.chassis_mass_kg, p.chassis_mass_kg);
  EXPECT_EQ(s.physics.wheel_mass_kg, p.wheel_mass_kg);
  EXPECT_EQ(s.physics.wheel_friction, p.wheel_friction);
  EXPECT_EQ(s.physics.support_friction, p.support_friction);
  EXPECT_EQ(s.physics.ground_friction, p.ground_friction);
  EXPECT_EQ(s.physics.max_wheel_torque_nm, p.max_wheel_torque_nm);
  EXPECT_EQ(s.physics.parked_robot_mass_kg, p.parked_robot_mass_kg);
  EXPECT_EQ(s.physics.obstacle_friction, p.obstacle_friction);
}

TEST(ScenarioReader, ObstacleDefaultsAreZeroYawAndTenCentimetres) {
  const Scenario s =
      parseScenario(valid("obstacles:\n"
                          "  - {name: b, kind: box, center: [1.0, 0.2], size: [0.4, 0.1]}\n"),
                    "t.yaml");
  ASSERT_EQ(s.obstacles.size(), 1u);
  const Obstacle& o = s.obstacles[0];
  EXPECT_EQ(o.name, "b");
  EXPECT_EQ(o.kind, ObstacleKind::kBox);
  EXPECT_EQ(o.box.center, Eigen::Vector2d(1.0, 0.2));
  EXPECT_EQ(o.box.half_extents, Eigen::Vector2d(0.2, 0.05));
  EXPECT_EQ(o.box.yaw, 0.0);
  EXPECT_EQ(o.height_m, 0.1);
}

TEST(ScenarioReader, EveryOptionalKeyOverridesItsField) {
  const Scenario s = parseScenario(
      "format: parksim-world/1\n"
      "name: all\n"
      "lot: {x_min: -1, y_min: -2, x_max: 3, y_max: 4}\n"
      // Parked robots before the robot: they must still use the overridden robot.
      "parked_robots:\n"
      "  - {name: p, pose: [2.0, 3.0, 180]}\n"
      "  - {name: q, pose: [2.0, 3.0, 0], height: 0.3}\n"
      "robot: {length: 0.2, width: 0.1, front_overhang: 0.05, wheel_base: 0.09,\n"
      "        wheel_radius: 0.03, max_wheel_speed_radps: 5, max_wheel_accel_radps2: 7,\n"
      "        height: 0.07}\n"
      "physics: {time_step_s: 0.01, solver_iterations: 20, gravity_mps2: 1.6,\n"
      "          chassis_mass_kg: 1, wheel_mass_kg: 0.1, wheel_friction: 0.8,\n"
      "          support_friction: 0.05, ground_friction: 0.9, max_wheel_torque_nm: 0.5,\n"
      "          parked_robot_mass_kg: 2, obstacle_friction: 0}\n"
      "obstacles:\n"
      "  - {name: c, kind: curb, center: [0, 3], size: [0.5, 0.02], yaw_deg: 30, height: 0.02}\n"
      "  - {name: w, kind: wall, center: [3, 0], size: [0.1, 1]}\n"
      "  - {name: i, kind: island, center: [1, 1], size: [0.2, 0.2]}\n"
      "start: [-0.9, -1.9, -45]\n"
      "goal: {pose: [2.9, 3.9, 45], position_tolerance: 0.01, heading_tolerance_deg: 2,\n"
      "       either_heading: true}\n",
      "all.yaml");
  EXPECT_EQ(s.robot.length_m, 0.2);
  EXPECT_EQ(s.robot.width_m, 0.1);
  EXPECT_EQ(s.robot.front_overhang_m, 0.05);
  EXPECT_EQ(s.robot.wheel_base_m, 0.09);
  EXPECT_EQ(s.robot.wheel_radius_m, 0.03);
  EXPECT_EQ(s.robot.max_wheel_speed_radps, 5.0);
  EXPECT_EQ(s.robot.max_wheel_accel_radps2, 7.0);
  EXPECT_EQ(s.robot.height_m, 0.07);

  EXPECT_EQ(s.physics.time_step_s, 0.01);
  EXPECT_EQ(s.physics.solver_iterations, 20);
  EXPECT_EQ(s.physics.gravity_mps2, 1.6);
  EXPECT_EQ(s.physics.chassis_mass_kg, 1.0);
  EXPECT_EQ(s.physics.wheel_mass_kg, 0.1);
  EXPECT_EQ(s.physics.wheel_friction, 0.8);
  EXPECT_EQ(s.physics.support_friction, 0.05);
  EXPECT_EQ(s.physics.ground_friction, 0.9);
  EXPECT_EQ(s.physics.max_wheel_torque_nm, 0.5);
  EXPECT_EQ(s.physics.parked_robot_mass_kg, 2.0);
  EXPECT_EQ(s.physics.obstacle_friction, 0.0);

  // Obstacles first in file order, then parked robots in file order.
  ASSERT_EQ(s.obstacles.size(), 5u);
  EXPECT_EQ(s.obstacles[0].kind, ObstacleKind::kCurb);
  EXPECT_EQ(s.obstacles[0].box.yaw, degToRad(30.0));
  EXPECT_EQ(s.obstacles[0].height_m, 0.02);
  EXPECT_EQ(s.obstacles[1].kind, ObstacleKind::kWall);
  EXPECT_EQ(s.obstacles[2].kind, ObstacleKind::kIsland);

  const Obstacle& p = s.obstacles[3];
  EXPECT_EQ(p.name, "p");
  EXPECT_EQ(p.kind, ObstacleKind::kParkedRobot);
  EXPECT_EQ(p.height_m, 0.07);  // the robot's height unless given
  const OrientedBox expected = footprintAt(s.robot, {2.0, 3.0, degToRad(180.0)});
  EXPECT_EQ(p.box.center, expected.center);
  EXPECT_NEAR(p.box.center.x(), 2.05, 1e-12);  // reference point 5 cm behind the centre
  EXPECT_EQ(p.box.half_extents, Eigen::Vector2d(0.1, 0.05));
  EXPECT_EQ(p.box.yaw, degToRad(180.0));
  EXPECT_EQ(s.obstacles[4].height_m, 0.3);

  EXPECT_EQ(s.start.theta, degToRad(-45.0));
  EXPECT_EQ(s.goal.position_tolerance_m, 0.01);
  EXPECT_EQ(s.goal.heading_tolerance_rad, degToRad(2.0));
  EXPECT_TRUE(s.goal.either_heading);
}

TEST(ScenarioReader, ParkedRobotFootprintPlacesTheReferencePointTenMillimetresBehindTheFront) {
  // The study's table row 8: x 0.70..0.78, y 1.115..1.2 is a robot facing +x at (0.77, 1.1575).
  const Scenario s = parseScenario(
      "format: parksim-world/1\nname: t\nlot: {x_min: 0, y_min: 0, x_max: 1.8, y_max: 1.2}\n"
      "parked_robots: [{name: r8, pose: [0.77, 1.1575, 0]}]\n"
      "start: [0.1, 0.1, 90]\ngoal: {pose: [1.2, 1.16, 0]}\n",
      "t.yaml");
  const OrientedBox& b = s.obstacles.at(0).box;
  EXPECT_NEAR(b.center.x(), 0.74, 1e-12);
  EXPECT_NEAR(b.center.y(), 1.1575, 1e-12);
  EXPECT_NEAR(b.half_extents.x(), 0.04, 1e-12);
  EXPECT_NEAR(b.half_extents.y(), 0.0425, 1e-12);
}

TEST(ScenarioReader, AcceptsWhatIsOnlyUnusual) {
  // A bumper exactly the placement margin from a wall face: 0.5 mm for the study's robot, and
  // for this 0.5 m one 0.5 mm x 0.5 / 0.085 = 2.941176470588235 mm. The footprint at
  // (0.5, 0.5, 0) spans x 0.125..0.625; the face at 0.627941176470588 computes to the margin
  // less a few ulps (the rounding that the rule forgives).
  EXPECT_EQ(errorOf(valid("robot: {length: 0.5, width: 0.25, front_overhang: 0.125}\n"
                          "obstacles: [{name: a, kind: box, center: [0.752941176470588, 0.5], "
                          "size: [0.25, 0.25]}]\n")),
            "(accepted)");
  // Parked robots overlapping each other and an obstacle are allowed.
  EXPECT_EQ(errorOf(valid("obstacles: [{name: a, kind: box, center: [1, 1], size: [0.2, 0.2]}]\n"
                          "parked_robots: [{name: p, pose: [1, 1, 0]}, "
                          "{name: q, pose: [1.01, 1, 0]}]\n")),
            "(accepted)");
  // The lot bounds the reference point only (with the 0.5 mm margin): a footprint may reach
  // past them.
  EXPECT_EQ(errorOf(std::string(kHead) +
                    "start: [0.0005, 0.0005, 0]\ngoal: {pose: [1.9995, 1.9995, 0]}\n"),
            "(accepted)");
  // Zero friction and zero front overhang are real designs; '+' signs and True are YAML.
  EXPECT_EQ(errorOf(valid("physics: {support_friction: 0, wheel_friction: +0.5}\n"
                          "robot: {front_overhang: 0}\n")),
            "(accepted)");
  EXPECT_EQ(errorOf(std::string(kHead) +
                    "start: [0.5, 0.5, 0]\ngoal: {pose: [1.5, 1.5, 90], either_heading: True}\n"),
            "(accepted)");
  // Empty lists are lists, and so is a key with nothing after it.
  EXPECT_EQ(errorOf(valid("obstacles: []\nparked_robots: []\n")), "(accepted)");
  EXPECT_EQ(errorOf(valid("obstacles:\nparked_robots:\n")), "(accepted)");
  // Whole degrees below one turn in radians, and any fraction above it, in the list form.
  EXPECT_EQ(errorOf(std::string(kHead) + "start: [0.5, 0.5, 6]\ngoal: {pose: [1.5, 1.5, 6.5]}\n"),
            "(accepted)");
}

TEST(ScenarioReader, HeadingsAreStoredAsWrittenInRadians) {
  const Scenario s = parseScenario(
      std::string(kHead) + "start: [0.5, 0.5, 270]\ngoal: {pose: [1.5, 1.5, -180]}\n", "t.yaml");
  EXPECT_EQ(s.start.theta, degToRad(270.0));
  EXPECT_EQ(s.goal.pose.theta, degToRad(-180.0));
}

TEST(ScenarioReader, ReadsCirclesAndConvexPolygonsInEitherWinding) {
  const Scenario s = parseScenario(
      valid("obstacles:\n"
            "  - {name: b, kind: bollard, center: [1.8, 0.2], radius: 0.03, height: 0.12}\n"
            "  - {name: cw, kind: curb, vertices: [[1.8, 1.0], [1.9, 0.9], [1.8, 0.8]]}\n"
            "  - {name: p, kind: pillar, center: [0.2, 1.8], radius: 0.1}\n"),
      "t.yaml");
  ASSERT_EQ(s.obstacles.size(), 3u);
  const Obstacle& b = s.obstacles[0];
  EXPECT_EQ(b.kind, ObstacleKind::kBollard);
  EXPECT_EQ(b.shape, ObstacleShape::kCircle);
  EXPECT_EQ(b.box.center, Eigen::Vector2d(1.8, 0.2));
  EXPECT_EQ(b.radius_m, 0.03);
  EXPECT_EQ(b.height_m, 0.12);
  const Obstacle& cw = s.obstacles[1];
  EXPECT_EQ(cw.shape, ObstacleShape::kPolygon);
  ASSERT_EQ(cw.vertices.size(), 3u);
  EXPECT_TRUE(isStrictlyConvexCcw(cw.vertices));  // written clockwise, stored counter-clockwise
  EXPECT_EQ(cw.vertices.front(), Eigen::Vector2d(1.8, 0.8));
  EXPECT_NEAR(cw.box.center.x(), 1.85, 1e-12);  // the bounding rectangle
  EXPECT_NEAR(cw.box.half_extents.y(), 0.1, 1e-12);
  EXPECT_EQ(s.obstacles[2].kind, ObstacleKind::kPillar);
}

TEST(ScenarioReader, ParkedVehiclesHaveTheirOwnSizeAndMass) {
  const Scenario s = parseScenario(
      valid("parked_robots:\n"
            "  - {name: van, pose: [1.5, 0.3, 90], length: 0.16, width: 0.1, mass_kg: 0.6}\n"
            "  - {name: car, pose: [0.3, 1.5, 0], length: 0.12, front_overhang: 0.03}\n"
            "  - {name: twin, pose: [1.5, 0.8, 0]}\n"),
      "t.yaml");
  ASSERT_EQ(s.obstacles.size(), 3u);
  RobotDef van;
  van.length_m = 0.16;
  van.width_m = 0.1;
  van.front_overhang_m = 0.02;  // the ego's 10 mm of 80 mm, scaled to 160 mm
  const OrientedBox expected = footprintAt(van, {1.5, 0.3, degToRad(90.0)});
  EXPECT_NEAR(s.obstacles[0].box.center.y(), expected.center.y(), 1e-15);
  EXPECT_EQ(s.obstacles[0].box.half_extents, Eigen::Vector2d(0.08, 0.05));
  EXPECT_EQ(s.obstacles[0].mass_kg, 0.6);
  EXPECT_NEAR(s.obstacles[1].box.center.x(), 0.3 + 0.03 - 0.06, 1e-15);
  EXPECT_EQ(s.obstacles[1].box.half_extents, Eigen::Vector2d(0.06, 0.0425));
  EXPECT_FALSE(s.obstacles[1].mass_kg.has_value());  // physics.parked_robot_mass_kg
  EXPECT_EQ(s.obstacles[2].box.half_extents, Eigen::Vector2d(0.04, 0.0425));
}

TEST(ScenarioReader, MapFormPosesSayTheirUnit) {
  const Scenario list = parseScenario(valid(), "t.yaml");
  const Scenario map = parseScenario(
      std::string(kHead) +
          "start: {x: 0.5, y: 0.5, yaw_deg: 0}\ngoal: {pose: {yaw_rad: 1.5, x: 1.5, y: 1.5}}\n",
      "t.yaml");
  EXPECT_EQ(map.start, list.start);
  EXPECT_EQ(map.goal.pose.x, 1.5);
  EXPECT_EQ(map.goal.pose.theta, 1.5);  // radians as written
  // Fractional degrees are fine in the map form.
  EXPECT_EQ(parseScenario(std::string(kHead) + "start: {x: 0.5, y: 0.5, yaw_deg: 1.5}\n"
                                               "goal: {pose: [1.5, 1.5, 90]}\n",
                          "t.yaml")
                .start.theta,
            degToRad(1.5));
}

TEST(ScenarioReader, MergeKeysCopyWhatTheMapDoesNotSay) {
  const Scenario s = parseScenario(
      valid("obstacles:\n"
            "  - &post {name: a, kind: bollard, center: [1.8, 0.2], radius: 0.03, height: 0.2}\n"
            "  - {<<: *post, name: b, center: [1.8, 0.4]}\n"
            "parked_robots:\n"
            "  - &p1 {name: p1, pose: [0.2, 1.8, 0], height: 0.3}\n"
            "  - &p2 {name: p2, pose: [0.2, 1.6, 0], length: 0.1, height: 0.7}\n"
            "  - {<<: [*p1, *p2], name: p3, pose: [0.2, 1.4, 0]}\n"),
      "t.yaml");
  ASSERT_EQ(s.obstacles.size(), 5u);
  EXPECT_EQ(s.obstacles[1].name, "b");
  EXPECT_EQ(s.obstacles[1].shape, ObstacleShape::kCircle);
  EXPECT_EQ(s.obstacles[1].box.center, Eigen::Vector2d(1.8, 0.4));
  EXPECT_EQ(s.obstacles[1].radius_m, 0.03);
  EXPECT_EQ(s.obstacles[1].height_m, 0.2);
  // Merging a list: the earlier map wins (height from p1), later ones fill in (length from p2).
  const Obstacle& p3 = s.obstacles[4];
  EXPECT_EQ(p3.name, "p3");
  EXPECT_EQ(p3.height_m, 0.3);
  EXPECT_EQ(p3.box.half_extents.x(), 0.05);
  // Keys are checked after merging: a merged typo is still an unknown field.
  EXPECT_EQ(errorOf(valid("obstacles:\n"
                          "  - &a {name: a, kind: box, center: [1.8, 0.2], size: [0.1, 0.1]}\n"
                          "  - {<<: *a, name: b, colour: red}\n")),
            "t.yaml:8: obstacles[1].colour: unknown field; expected one of: name, kind, center, "
            "size, yaw_deg, radius, vertices, holes, height");
}

// Merge keys are resolved with each merged map visited once: a map that merges itself
// (directly or round a cycle) adds nothing the second time, a fan-out of aliases ("billion
// laughs", 4^30 paths here) costs its distinct maps, and a map that brings in more than
// kMaxMergedItems maps and keys is refused. They used to overflow the stack and run for hours.
TEST(ScenarioReader, MergeKeysAreBoundedAndCyclesEnd) {
  const Scenario cycle = parseScenario(
      valid("obstacles:\n"
            "  - &r {name: r, kind: bollard, center: [1.8, 0.2], radius: 0.03, <<: *r}\n"),
      "t.yaml");
  ASSERT_EQ(cycle.obstacles.size(), 1u);
  EXPECT_EQ(cycle.obstacles[0].radius_m, 0.03);

  std::string bomb =
      "obstacles:\n  - &m0 {name: m0, kind: bollard, center: [1.8, 0.2], "
      "radius: 0.03}\n";
  for (int i = 1; i < 30; ++i) {
    const std::string prev = "*m" + std::to_string(i - 1);
    bomb += "  - &m" + std::to_string(i) + " {<<: [" + prev + ", " + prev + ", " + prev + ", " +
            prev + "], name: m" + std::to_string(i) + "}\n";
  }
  const Scenario fanned = parseScenario(valid(bomb), "t.yaml");
  ASSERT_EQ(fanned.obstacles.size(), 30u);
  EXPECT_EQ(fanned.obstacles[29].radius_m, 0.03);

  // Two chains that merge each other: every distinct map counts once, and the limit stops it.
  std::string chains =
      "obstacles:\n  - &a0 {name: a0, kind: bollard, center: [1.8, 0.2], "
      "radius: 0.03}\n  - &b0 {name: b0, kind: bollard, center: [1.8, 0.2], "
      "radius: 0.03}\n";
  for (int i = 1; i < 60; ++i) {
    const std::string n = std::to_string(i);
    const std::string p = std::to_string(i - 1);
    chains += "  - &a" + n + " {<<: [*a" + p + ", *b" + p + "], name: a" + n + "}\n";
    chains += "  - &b" + n + " {<<: [*b" + p + ", *a" + p + "], name: b" + n + "}\n";
  }
  const std::string message = errorOf(valid(chains));
  EXPECT_NE(message.find("merge keys bring in more than 256 maps and keys"), std::string::npos)
      << message;
}

TEST(ScenarioReader, LowObstaclesDoNotBlockTheStart) {
  // A 1 mm painted line under the start: below the 2 mm ground clearance.
  EXPECT_EQ(errorOf(valid("obstacles: [{name: line, kind: curb, center: [0.5, 0.5], "
                          "size: [0.02, 0.5], height: 0.001}]\n")),
            "(accepted)");
  EXPECT_EQ(errorOf(valid("robot: {ground_clearance: 0.0005}\n"
                          "obstacles: [{name: line, kind: curb, center: [0.5, 0.5], "
                          "size: [0.02, 0.5], height: 0.001}]\n")),
            "t.yaml:4: start: robot footprint overlaps obstacle \"line\"");
}

TEST(ScenarioReader, EitherHeadingGoalIsPlacedWhenOneHeadingFits) {
  // A post 45 mm behind the goal: only the turned goal pose is clear of it.
  const std::string obstacles =
      "obstacles: [{name: post, kind: box, center: [1.435, 1.5], size: [0.04, 0.04]}]\n";
  EXPECT_EQ(errorOf(std::string(kHead) + "start: [0.5, 0.5, 0]\ngoal: {pose: [1.5, 1.5, 0]}\n" +
                    obstacles),
            "t.yaml:5: goal.pose: robot footprint overlaps obstacle \"post\"");
  EXPECT_EQ(errorOf(std::string(kHead) +
                    "start: [0.5, 0.5, 0]\ngoal: {pose: [1.5, 1.5, 0], either_heading: true}\n" +
                    obstacles),
            "(accepted)");
}

TEST(ScenarioReader, ParsePoseReadsTheCommandLineForms) {
  EXPECT_EQ(parsePose("0.1,0.2,90", "--start"), (Pose2{0.1, 0.2, degToRad(90.0)}));
  EXPECT_EQ(parsePose("[0.1, 0.2, -45]", "--goal"), (Pose2{0.1, 0.2, degToRad(-45.0)}));
  EXPECT_EQ(parsePose("{x: 0.1, y: 0.2, yaw_rad: 1}", "--goal"), (Pose2{0.1, 0.2, 1.0}));
  const auto error = [](std::string_view text) {
    try {
      parsePose(text, "--start");
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("(accepted)");
  };
  EXPECT_EQ(error("0.1,abc,90"), "--start[1]: must be a number, got abc");
  EXPECT_EQ(error("0.1,0.2"),
            "--start: must be a list [x, y, yaw_deg] of 3 numbers or a map {x, y, yaw_deg}, got "
            "a list of 2");
  EXPECT_EQ(error("0.1,0.2,1.5708"),
            "--start[2]: the list form's angle is in degrees, and 1.5708 looks like radians; "
            "write whole degrees (90 if that was radians), or the map form "
            "{x: .., y: .., yaw_deg: ..} or {x: .., y: .., yaw_rad: ..}");
  EXPECT_EQ(error("0.1,0.2,.inf"), "--start[2]: must be a finite number, got .inf");
}

TEST(ScenarioReader, ListsLongerThanTheLimitAreRefusedBeforeTheyAreRead) {
  std::string many = "obstacles: [";
  for (std::size_t i = 0; i <= kMaxObstacles; ++i) many += "{},";
  many += "]\n";
  EXPECT_EQ(errorOf(valid(many)),
            "t.yaml:6: obstacles: holds 10001 items; at most 10000 are allowed");
  std::string parked = "parked_robots: [";
  for (std::size_t i = 0; i <= kMaxParkedRobots; ++i) parked += "{},";
  parked += "]\n";
  EXPECT_EQ(errorOf(valid(parked)),
            "t.yaml:6: parked_robots: holds 10001 items; at most 10000 are allowed");
}

TEST(ScenarioReader, NonUtf8NamesAreRefusedAndEscaped) {
  // yaml-cpp may refuse the byte itself; either way the message holds no raw byte.
  const std::string message =
      errorOf("format: parksim-world/1\nname: \"caf\xe9\"\n" + std::string(kStartGoal));
  EXPECT_EQ(message.find('\xe9'), std::string::npos) << message;
  EXPECT_NE(message, "(accepted)");
}

// ---- Files ---------------------------------------------------------------------------------

class ScenarioFile : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::path(::testing::TempDir()) /
           ("parksim_scenario_" +
            std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  std::string write(const std::string& name, std::string_view text) {
    const std::string path = (dir_ / name).string();
    std::ofstream(path, std::ios::binary) << text;
    return path;
  }

  std::filesystem::path dir_;
};

TEST_F(ScenarioFile, LoadsAndRemembersItsPath) {
  const std::string path = write("w.yaml", valid());
  const Scenario s = loadScenario(path);
  EXPECT_EQ(s.source_path, path);
  EXPECT_EQ(s.name, "t");
}

TEST_F(ScenarioFile, ErrorsNameTheFileAsGiven) {
  const std::string path = write("bad.yaml", valid("obstacles: [{name: a}]\n"));
  try {
    loadScenario(path);
    FAIL() << "accepted";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()), path + ":6: obstacles[0].kind: missing required field");
  }
}

TEST_F(ScenarioFile, MissingFileIsReported) {
  const std::string path = (dir_ / "absent.yaml").string();
  try {
    loadScenario(path);
    FAIL() << "accepted";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()), path + ": cannot open: No such file or directory");
  }
}

TEST_F(ScenarioFile, DirectoryIsReported) {
  try {
    loadScenario(dir_.string());
    FAIL() << "accepted";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()), dir_.string() + ": cannot open: is a directory");
  }
}

TEST_F(ScenarioFile, OversizedFileIsRefusedBeforeReading) {
  const std::string path = write("big.yaml", valid() + std::string(kMaxWorldFileBytes, '#'));
  try {
    loadScenario(path);
    FAIL() << "accepted";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()),
              path + ": file size: " + std::to_string(valid().size() + kMaxWorldFileBytes) +
                  " bytes; a world file may hold at most 1048576 bytes (1 MiB)");
  }
}

TEST_F(ScenarioFile, DevicesAreNotWorldFiles) {
  try {
    loadScenario("/dev/zero");
    FAIL() << "accepted";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()), "/dev/zero: cannot open: not a regular file");
  }
}

TEST_F(ScenarioFile, ShowcaseWorldHasEveryShape) {
  const Scenario s = loadScenario(parksim::testing::sourceDir() + "/worlds/bollards.yaml");
  int circles = 0;
  int polygons = 0;
  int low = 0;
  for (const Obstacle& o : s.obstacles) {
    circles += o.shape == ObstacleShape::kCircle;
    polygons += o.shape == ObstacleShape::kPolygon;
    low += !blocksRobot(o, s.robot);
  }
  EXPECT_EQ(circles, 3);
  EXPECT_EQ(polygons, 1);
  EXPECT_EQ(low, 1);
  const Obstacle& van = s.obstacles.back();
  EXPECT_EQ(van.kind, ObstacleKind::kParkedRobot);
  EXPECT_GT(van.box.half_extents.x(), s.robot.length_m / 2);
  EXPECT_GT(van.box.half_extents.y(), s.robot.width_m / 2);
  EXPECT_EQ(s.obstacles[2].radius_m, s.obstacles[1].radius_m);  // merged from the first
}

TEST_F(ScenarioFile, DocumentationExampleIsAValidWorld) {
  // Keeps docs/world-format.md honest: its complete example must load as documented.
  std::ifstream in(parksim::testing::sourceDir() + "/docs/world-format.md");
  ASSERT_TRUE(in) << "docs/world-format.md is missing";
  const std::string doc((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::size_t section = doc.find("## A complete example");
  ASSERT_NE(section, std::string::npos);
  const std::size_t begin = doc.find("```yaml\n", section);
  ASSERT_NE(begin, std::string::npos);
  const std::size_t end = doc.find("```", begin + 8);
  ASSERT_NE(end, std::string::npos);
  const Scenario s = parseScenario(doc.substr(begin + 8, end - begin - 8), "example.yaml");
  EXPECT_EQ(s.name, "one_space");
  EXPECT_EQ(s.robot.max_wheel_speed_radps, 8.0);
  ASSERT_EQ(s.obstacles.size(), 5u);
  EXPECT_EQ(s.obstacles[1].box.yaw, degToRad(10.0));
  EXPECT_EQ(s.obstacles[2].shape, ObstacleShape::kCircle);
  EXPECT_EQ(s.obstacles[3].shape, ObstacleShape::kPolygon);
  EXPECT_EQ(s.obstacles[4].kind, ObstacleKind::kParkedRobot);
  EXPECT_TRUE(s.goal.either_heading);
  EXPECT_EQ(s.physics.solver_iterations, 80);
}

// ---- Rejected input: every case with its exact one-line message -----------------------------

struct BadCase {
  const char* name;
  std::string yaml;
  const char* message;
};

class RejectsBadInput : public ::testing::TestWithParam<BadCase> {};

TEST_P(RejectsBadInput, WithExactMessage) {
  EXPECT_EQ(errorOf(GetParam().yaml), GetParam().message);
}

std::string head(std::string_view rest) { return std::string(kHead) + std::string(rest); }

const BadCase kBadCases[] = {
    // Document and syntax.
    {"EmptyFile", "",
     "t.yaml:1: (document): empty; a world file is a map that starts with format: "
     "parksim-world/1"},
    {"OnlyComments", "# nothing here\n",
     "t.yaml:1: (document): empty; a world file is a map that starts with format: "
     "parksim-world/1"},
    {"RootIsAList", "- format\n- name\n", "t.yaml:1: (document): must be a map, got a list of 2"},
    {"TwoDocuments", valid("---\nname: u\n"),
     "t.yaml:7: (document): a world file holds one YAML document, found 2"},
    {"UnclosedFlowList", head("start: [0.5, 0.5, 0\ngoal: {pose: [1.5, 1.5, 90]}\n"),
     "t.yaml:5: (syntax): end of sequence flow not found"},
    {"BadIndentation", "format: parksim-world/1\nname: t\n  lot: 3\n",
     "t.yaml:3: (syntax): illegal map value"},

    // Format.
    {"WrongFormat", "format: parksim-world/2\nname: t\n",
     "t.yaml:1: format: expected \"parksim-world/1\", got \"parksim-world/2\""},
    {"WrongFormatIsReportedBeforeUnknownKeys", "format: parksim-world/2\nnew_key: 1\n",
     "t.yaml:1: format: expected \"parksim-world/1\", got \"parksim-world/2\""},
    {"MissingFormat", "name: t\n", "t.yaml:1: format: missing required field"},

    // Missing required fields.
    {"MissingName", "format: parksim-world/1\n", "t.yaml:1: name: missing required field"},
    {"MissingLot", "format: parksim-world/1\nname: t\n", "t.yaml:1: lot: missing required field"},
    {"MissingStart", head("goal: {pose: [1.5, 1.5, 90]}\n"),
     "t.yaml:1: start: missing required field"},
    {"MissingGoal", head("start: [0.5, 0.5, 0]\n"), "t.yaml:1: goal: missing required field"},
    {"MissingGoalPose", head("start: [0.5, 0.5, 0]\ngoal:\n  either_heading: true\n"),
     "t.yaml:5: goal.pose: missing required field"},
    {"MissingLotBound", "format: parksim-world/1\nname: t\nlot: {x_min: 0, y_min: 0, x_max: 2}\n",
     "t.yaml:3: lot.y_max: missing required field"},
    {"MissingObstacleSize", valid("obstacles:\n  - {name: a, kind: box, center: [1, 1]}\n"),
     "t.yaml:7: obstacles[0]: give exactly one shape: size (a box), radius (a circle) or "
     "vertices (a polygon)"},
    {"MissingObstacleName", valid("obstacles:\n  - kind: box\n"),
     "t.yaml:7: obstacles[0].name: missing required field"},
    {"MissingParkedRobotPose", valid("parked_robots:\n  - name: p\n"),
     "t.yaml:7: parked_robots[0].pose: missing required field"},

    // Unknown fields, at every level.
    {"UnknownTopLevelField", valid("nmae: t\n"),
     "t.yaml:6: nmae: unknown field; expected one of: format, name, lot, map, robot, obstacles, "
     "parked_robots, start, goal, physics, realism, tolerance"},
    {"UnknownLotField", "format: parksim-world/1\nname: t\nlot: {x_min: 0, y_min: 0, z_max: 1}\n",
     "t.yaml:3: lot.z_max: unknown field; expected one of: x_min, y_min, x_max, y_max"},
    {"UnknownRobotField", valid("robot:\n  length: 0.08\n  lenght: 0.09\n"),
     "t.yaml:8: robot.lenght: unknown field; expected one of: drive, length, width, "
     "front_overhang, wheel_base, wheel_radius, max_wheel_speed_radps, max_wheel_accel_radps2, "
     "height, ground_clearance"},
    {"UnknownPhysicsFieldWithoutUnitSuffix", valid("physics: {time_step: 0.01}\n"),
     "t.yaml:6: physics.time_step: unknown field; expected one of: time_step_s, "
     "solver_iterations, gravity_mps2, chassis_mass_kg, wheel_mass_kg, wheel_friction, "
     "support_friction, ground_friction, max_wheel_torque_nm, parked_robot_mass_kg, "
     "obstacle_friction"},
    {"UnknownGoalField", head("start: [0.5, 0.5, 0]\ngoal: {pose: [1.5, 1.5, 90], tolerance: 1}\n"),
     "t.yaml:5: goal.tolerance: unknown field; expected one of: pose, position_tolerance, "
     "heading_tolerance_deg, either_heading"},
    {"UnknownObstacleField", valid("obstacles:\n  - name: a\n    kind: box\n    colour: red\n"),
     "t.yaml:9: obstacles[0].colour: unknown field; expected one of: name, kind, center, size, "
     "yaw_deg, radius, vertices, holes, height"},
    {"UnknownParkedRobotField",
     valid("parked_robots:\n  - {name: p, pose: [1, 1, 0]}\n  - {name: q, yaw_deg: 3}\n"),
     "t.yaml:8: parked_robots[1].yaw_deg: unknown field; expected one of: name, pose, height, "
     "length, width, front_overhang, mass_kg"},
    {"DuplicateKey", valid("lot: {x_min: 0, y_min: 0, x_max: 3, y_max: 3}\n"),
     "t.yaml:6: lot: duplicate key"},
    {"DuplicateNestedKey",
     head("start: [0.5, 0.5, 0]\ngoal:\n  pose: [1, 1, 0]\n  pose: [1, 2, 0]\n"),
     "t.yaml:7: goal.pose: duplicate key"},

    // Wrong types.
    {"TextWhereNumberExpected", head("start: [0.5, abc, 0]\ngoal: {pose: [1.5, 1.5, 90]}\n"),
     "t.yaml:4: start[1]: must be a number, got abc"},
    {"QuotedNumber", head("start: [\"0.5\", 0.5, 0]\ngoal: {pose: [1.5, 1.5, 90]}\n"),
     "t.yaml:4: start[0]: must be a number, got the string \"0.5\""},
    {"NumberWithTrailingText", head("start: [0.5m, 0.5, 0]\ngoal: {pose: [1.5, 1.5, 90]}\n"),
     "t.yaml:4: start[0]: must be a number, got 0.5m"},
    {"PoseTooShort", head("start: [0.5, 0.5]\ngoal: {pose: [1.5, 1.5, 90]}\n"),
     "t.yaml:4: start: must be a list [x, y, yaw_deg] of 3 numbers or a map {x, y, yaw_deg}, "
     "got a list of 2"},
    {"PoseMapWithoutHeading", head("start: {x: 0.5, y: 0.5}\ngoal: {pose: [1.5, 1.5, 90]}\n"),
     "t.yaml:4: start.yaw_deg: missing required field (or yaw_rad)"},
    {"PoseMapWithBothHeadings",
     head("start: {x: 0.5, y: 0.5, yaw_deg: 0, yaw_rad: 0}\ngoal: {pose: [1.5, 1.5, 90]}\n"),
     "t.yaml:4: start.yaw_rad: give the heading once: yaw_deg or yaw_rad, not both"},
    {"PoseMapUnknownKey", head("start: {x: 0.5, y: 0.5, theta: 0}\ngoal: {pose: [1.5, 1.5, 90]}\n"),
     "t.yaml:4: start.theta: unknown field; expected one of: x, y, yaw_deg, yaw_rad"},
    {"PoseEmpty", head("start:\ngoal: {pose: [1.5, 1.5, 90]}\n"),
     "t.yaml:4: start: must be a list [x, y, yaw_deg] of 3 numbers or a map {x, y, yaw_deg}, "
     "got null"},
    {"RadiansOutOfHabit", head("start: [0.15, 0.6, 1.5708]\ngoal: {pose: [1.5, 1.5, 90]}\n"),
     "t.yaml:4: start[2]: the list form's angle is in degrees, and 1.5708 looks like radians; "
     "write whole degrees (90 if that was radians), or the map form {x: .., y: .., yaw_deg: ..} "
     "or {x: .., y: .., yaw_rad: ..}"},
    {"NegativeRadiansOutOfHabit",
     head("start: [0.5, 0.5, 0]\ngoal: {pose: [1.5, 1.5, -3.14159]}\n"),
     "t.yaml:5: goal.pose[2]: the list form's angle is in degrees, and -3.14159 looks like "
     "radians; write whole degrees (-180 if that was radians), or the map form "
     "{x: .., y: .., yaw_deg: ..} or {x: .., y: .., yaw_rad: ..}"},
    {"SizeTooLong", valid("obstacles: [{name: a, kind: box, center: [1, 1], size: [1, 2, 3]}]\n"),
     "t.yaml:6: obstacles[0].size: must be a list [sx, sy] of 2 numbers, got a list of 3"},
    {"LotAsList", "format: parksim-world/1\nname: t\nlot: [0, 0, 2, 2]\n",
     "t.yaml:3: lot: must be a map, got a list of 4"},
    {"ObstaclesAsMap", valid("obstacles: {name: a}\n"),
     "t.yaml:6: obstacles: must be a list, got a map"},
    {"ObstacleAsScalar", valid("obstacles:\n  - wall\n"),
     "t.yaml:7: obstacles[0]: must be a map, got wall"},
    {"RobotAsScalar", valid("robot: small\n"), "t.yaml:6: robot: must be a map, got small"},
    {"NameAsList", "format: parksim-world/1\nname: [a, b]\n",
     "t.yaml:2: name: must be a string, got a list of 2"},
    {"EmptyName", "format: parksim-world/1\nname: \"\"\n", "t.yaml:2: name: must not be empty"},
    {"YesIsNotABoolean",
     head("start: [0.5, 0.5, 0]\ngoal:\n  pose: [1.5, 1.5, 90]\n  either_heading: yes\n"),
     "t.yaml:7: goal.either_heading: must be true or false, got yes"},
    {"FractionalSolverIterations", valid("physics: {solver_iterations: 2.5}\n"),
     "t.yaml:6: physics.solver_iterations: must be an integer, got 2.5"},

    // Zero or negative sizes, lengths, tolerances, masses, time step.
    {"NegativeObstacleSize",
     valid("obstacles:\n"
           "  - {name: a, kind: wall, center: [1, 1], size: [0.1, 0.1]}\n"
           "  - {name: b, kind: wall, center: [1, 1], size: [0.1, 0.1]}\n"
           "  - name: c\n"
           "    kind: curb\n"
           "    center: [1, 1]\n"
           "    size: [-0.1,\n"
           "           0.1]\n"),
     "t.yaml:12: obstacles[2].size[0]: must be positive, got -0.1"},
    {"ZeroObstacleSize", valid("obstacles: [{name: a, kind: box, center: [1, 1], size: [1, 0]}]\n"),
     "t.yaml:6: obstacles[0].size[1]: must be positive, got 0"},
    {"ZeroObstacleHeight",
     valid("obstacles: [{name: a, kind: box, center: [1, 1], size: [1, 1], height: 0}]\n"),
     "t.yaml:6: obstacles[0].height: must be positive, got 0"},
    {"NegativeParkedRobotHeight",
     valid("parked_robots: [{name: p, pose: [1, 1, 0], height: -1}]\n"),
     "t.yaml:6: parked_robots[0].height: must be positive, got -1"},
    {"ZeroRobotLength", valid("robot: {length: 0}\n"),
     "t.yaml:6: robot.length: must be positive, got 0"},
    {"NegativeRobotWidth", valid("robot: {width: -0.085}\n"),
     "t.yaml:6: robot.width: must be positive, got -0.085"},
    {"ZeroWheelBase", valid("robot: {wheel_base: 0}\n"),
     "t.yaml:6: robot.wheel_base: must be positive, got 0"},
    {"NegativeWheelRadius", valid("robot: {wheel_radius: -0.02}\n"),
     "t.yaml:6: robot.wheel_radius: must be positive, got -0.02"},
    {"ZeroMaxWheelSpeed", valid("robot: {max_wheel_speed_radps: 0}\n"),
     "t.yaml:6: robot.max_wheel_speed_radps: must be positive, got 0"},
    {"ZeroMaxWheelAccel", valid("robot: {max_wheel_accel_radps2: 0}\n"),
     "t.yaml:6: robot.max_wheel_accel_radps2: must be positive, got 0"},
    {"ZeroRobotHeight", valid("robot: {height: 0}\n"),
     "t.yaml:6: robot.height: must be positive, got 0"},
    {"NegativeFrontOverhang", valid("robot: {front_overhang: -0.01}\n"),
     "t.yaml:6: robot.front_overhang: must be zero or positive, got -0.01"},
    {"FrontOverhangBeyondLength", valid("robot: {length: 0.08, front_overhang: 0.1}\n"),
     "t.yaml:6: robot.front_overhang: must not exceed robot.length (0.08), got 0.1"},
    {"LengthShorterThanDefaultOverhang", valid("robot:\n  length: 0.005\n"),
     "t.yaml:7: robot.length: must be at least robot.front_overhang (0.01), got 0.005"},
    {"ZeroPositionTolerance",
     head("start: [0.5, 0.5, 0]\ngoal: {pose: [1.5, 1.5, 90], position_tolerance: 0}\n"),
     "t.yaml:5: goal.position_tolerance: must be positive, got 0"},
    {"NegativeHeadingTolerance",
     head("start: [0.5, 0.5, 0]\ngoal: {pose: [1.5, 1.5, 90], heading_tolerance_deg: -1}\n"),
     "t.yaml:5: goal.heading_tolerance_deg: must be positive, got -1"},
    {"ZeroTimeStep", valid("physics:\n  time_step_s: 0\n"),
     "t.yaml:7: physics.time_step_s: must be positive, got 0"},
    {"ZeroSolverIterations", valid("physics: {solver_iterations: 0}\n"),
     "t.yaml:6: physics.solver_iterations: must be positive, got 0"},
    {"ZeroGravity", valid("physics: {gravity_mps2: 0}\n"),
     "t.yaml:6: physics.gravity_mps2: must be positive, got 0"},
    {"NegativeChassisMass", valid("physics: {chassis_mass_kg: -0.2}\n"),
     "t.yaml:6: physics.chassis_mass_kg: must be positive, got -0.2"},
    {"ZeroWheelMass", valid("physics: {wheel_mass_kg: 0}\n"),
     "t.yaml:6: physics.wheel_mass_kg: must be positive, got 0"},
    {"ZeroParkedRobotMass", valid("physics: {parked_robot_mass_kg: 0}\n"),
     "t.yaml:6: physics.parked_robot_mass_kg: must be positive, got 0"},
    {"ZeroMaxTorque", valid("physics: {max_wheel_torque_nm: 0}\n"),
     "t.yaml:6: physics.max_wheel_torque_nm: must be positive, got 0"},
    {"NegativeFriction", valid("physics: {ground_friction: -0.1}\n"),
     "t.yaml:6: physics.ground_friction: must be zero or positive, got -0.1"},

    // NaN and infinities.
    {"NanInPose", head("start: [.nan, 0.5, 0]\ngoal: {pose: [1.5, 1.5, 90]}\n"),
     "t.yaml:4: start[0]: must be a finite number, got .nan"},
    {"NanSpelledAsCpp", head("start: [0.5, 0.5, nan]\ngoal: {pose: [1.5, 1.5, 90]}\n"),
     "t.yaml:4: start[2]: must be a finite number, got nan"},
    {"InfInSize", valid("obstacles: [{name: a, kind: box, center: [1, 1], size: [.inf, 1]}]\n"),
     "t.yaml:6: obstacles[0].size[0]: must be a finite number, got .inf"},
    {"MinusInfInLot",
     "format: parksim-world/1\nname: t\nlot: {x_min: -.inf, y_min: 0, x_max: 2, "
     "y_max: 2}\n",
     "t.yaml:3: lot.x_min: must be a finite number, got -.inf"},
    {"NanTolerance",
     head("start: [0.5, 0.5, 0]\ngoal: {pose: [1.5, 1.5, 90], heading_tolerance_deg: .NaN}\n"),
     "t.yaml:5: goal.heading_tolerance_deg: must be a finite number, got .NaN"},
    {"InfTimeStep", valid("physics: {time_step_s: .Inf}\n"),
     "t.yaml:6: physics.time_step_s: must be a finite number, got .Inf"},
    {"InfYaw",
     valid("obstacles: [{name: a, kind: box, center: [1, 1], size: [1, 1], "
           "yaw_deg: +.inf}]\n"),
     "t.yaml:6: obstacles[0].yaw_deg: must be a finite number, got +.inf"},

    // Lot.
    {"LotXMaxEqualsXMin",
     "format: parksim-world/1\nname: t\nlot: {x_min: 0, y_min: 0, x_max: 0, "
     "y_max: 2}\n",
     "t.yaml:3: lot.x_max: must be greater than lot.x_min (0), got 0"},
    {"LotYMaxBelowYMin",
     "format: parksim-world/1\nname: t\nlot:\n  x_min: 0\n  y_min: 1.5\n  x_max: 2\n  y_max: 1\n",
     "t.yaml:7: lot.y_max: must be greater than lot.y_min (1.5), got 1"},

    // Start and goal placement.
    {"StartOutsideLot", head("start: [2.5, 0.5, 0]\ngoal: {pose: [1.5, 1.5, 90]}\n"),
     "t.yaml:4: start: reference point (2.5, 0.5) is outside the lot [0, 2] x [0, 2]"},
    {"GoalOutsideLot", head("start: [0.5, 0.5, 0]\ngoal:\n  pose: [1.5, -0.1, 90]\n"),
     "t.yaml:6: goal.pose: reference point (1.5, -0.1) is outside the lot [0, 2] x [0, 2]"},
    {"StartInCollision",
     valid("obstacles:\n"
           "  - {name: far, kind: wall, center: [1.9, 0.1], size: [0.1, 0.1]}\n"
           "  - {name: pillar, kind: box, center: [0.6, 0.5], size: [0.2, 0.2]}\n"),
     "t.yaml:4: start: robot footprint overlaps obstacle \"pillar\""},
    {"StartInCollisionWithRotatedObstacle",
     // The footprint's front edge is at x = 0.51; the diamond's left corner, 0.0707 left of
     // its centre, is at x ~ 0.509: 1 mm inside, though its own edges lean away.
     valid("obstacles: [{name: diamond, kind: box, center: [0.58, 0.5], size: [0.1, 0.1], "
           "yaw_deg: 45}]\n"),
     "t.yaml:4: start: robot footprint overlaps obstacle \"diamond\""},
    {"GoalInCollisionWithParkedRobot",
     valid("parked_robots:\n  - {name: neighbour, pose: [1.55, 1.5, 90]}\n"),
     "t.yaml:5: goal.pose: robot footprint overlaps obstacle \"neighbour\""},

    // Names and kinds.
    {"DuplicateNameAcrossLists",
     valid("obstacles:\n  - {name: a, kind: box, center: [1, 0.1], size: [0.1, 0.1]}\n"
           "parked_robots:\n  - {name: a, pose: [1.8, 0.2, 0]}\n"),
     "t.yaml:9: parked_robots[0].name: duplicate name \"a\" (already used at line 7)"},
    {"DuplicateObstacleName",
     valid("obstacles:\n  - {name: a, kind: box, center: [1, 0.1], size: [0.1, 0.1]}\n"
           "  - {name: a, kind: box, center: [1, 0.3], size: [0.1, 0.1]}\n"),
     "t.yaml:8: obstacles[1].name: duplicate name \"a\" (already used at line 7)"},
    {"UnknownKind", valid("obstacles: [{name: a, kind: wal, center: [1, 1], size: [1, 1]}]\n"),
     "t.yaml:6: obstacles[0].kind: unknown kind \"wal\"; expected one of: wall, curb, island, "
     "box, bollard, pillar"},
    {"ParkedRobotKindInObstacles",
     valid("obstacles: [{name: a, kind: parked_robot, center: [1, 1], size: [1, 1]}]\n"),
     "t.yaml:6: obstacles[0].kind: parked robots are listed under parked_robots, with a pose "
     "instead of a size"},

    // Hardening: inputs that once hung, overflowed or echoed raw bytes.
    {"StrayComma", ",", "t.yaml:1: (syntax): unexpected ',' (outside any [ ] or { } list or map)"},
    {"StrayCommaAfterTheWorld", valid(",\n"), "t.yaml:6: (syntax): end of map not found"},
    {"StrayCommaAfterAFlowMap", "{format: parksim-world/1, name: t},\n",
     "t.yaml:1: (syntax): unexpected ',' (outside any [ ] or { } list or map)"},
    {"OverflowIsNotFinite", head("start: [1e309, 0.5, 0]\ngoal: {pose: [1.5, 1.5, 90]}\n"),
     "t.yaml:4: start[0]: must be a finite number, got 1e309"},
    {"NegativeOverflowIsNotFinite", head("start: [0.5, -1e400, 0]\ngoal: {pose: [1.5, 1.5, 90]}\n"),
     "t.yaml:4: start[1]: must be a finite number, got -1e400"},
    {"HugeYawIsOutOfRange", head("start: [0.5, 0.5, 1e308]\ngoal: {pose: [1.5, 1.5, 90]}\n"),
     "t.yaml:4: start[2]: must be in [-3600, 3600] degrees, got 1e308"},
    {"HugeObstacleYawIsBlamedOnItsField",
     valid("obstacles: [{name: a, kind: box, center: [1.9, 0.1], size: [0.1, 0.1], "
           "yaw_deg: 1e308}]\n"),
     "t.yaml:6: obstacles[0].yaw_deg: must be in [-3600, 3600] degrees, got 1e308"},
    {"HugeCoordinate",
     "format: parksim-world/1\nname: t\nlot: {x_min: 0, y_min: 0, x_max: 1e300, "
     "y_max: 2}\n",
     "t.yaml:3: lot.x_max: must be in [-10000, 10000], got 1e300"},
    {"HugeSize", valid("obstacles: [{name: a, kind: box, center: [1, 1], size: [1e6, 1]}]\n"),
     "t.yaml:6: obstacles[0].size[0]: must be positive and at most 10000 m, got 1e6"},
    {"TerminalEscapeInNameIsEscaped", "format: parksim-world/1\nname: \"\\e[31mred\"\n",
     "t.yaml:2: name: must be UTF-8 text without control characters, got \"\\x1b[31mred\""},
    {"TerminalEscapeInKeyIsEscaped", valid("\"\\e[2J\": 1\n"),
     "t.yaml:6: \\x1b[2J: unknown field; expected one of: format, name, lot, map, robot, "
     "obstacles, "
     "parked_robots, start, goal, physics, realism, tolerance"},
    {"ControlCharacterInObstacleName",
     valid("obstacles: [{name: \"a\\tb\", kind: box, center: [1.9, 0.1], size: [0.1, 0.1]}]\n"),
     "t.yaml:6: obstacles[0].name: must be UTF-8 text without control characters, got \"a\\tb\""},

    // Shapes.
    {"TwoShapes",
     valid("obstacles: [{name: a, kind: box, center: [1, 1], size: [1, 1], radius: 0.1}]\n"),
     "t.yaml:6: obstacles[0]: give exactly one shape: size (a box), radius (a circle) or "
     "vertices (a polygon)"},
    {"CircleWithYaw",
     valid("obstacles: [{name: a, kind: bollard, center: [1.9, 0.1], radius: 0.05, "
           "yaw_deg: 10}]\n"),
     "t.yaml:6: obstacles[0].yaw_deg: a circle has no heading"},
    {"ZeroRadius", valid("obstacles: [{name: a, kind: bollard, center: [1, 1], radius: 0}]\n"),
     "t.yaml:6: obstacles[0].radius: must be positive, got 0"},
    {"PolygonWithCenter",
     valid("obstacles: [{name: a, kind: island, center: [1, 1], "
           "vertices: [[1.8, 0], [1.9, 0], [1.9, 0.1]]}]\n"),
     "t.yaml:6: obstacles[0].center: a polygon is placed by its vertices alone"},
    {"PolygonOfTwoVertices",
     valid("obstacles: [{name: a, kind: island, vertices: [[1.8, 0], [1.9, 0]]}]\n"),
     "t.yaml:6: obstacles[0].vertices: a polygon needs at least 3 vertices [x, y], got 2"},
    {"SelfCrossingPolygon",
     valid("obstacles:\n  - name: a\n    kind: island\n"
           "    vertices: [[1.6, 0], [1.9, 0.3], [1.9, 0], [1.6, 0.2]]\n"),
     "t.yaml:9: obstacles[0].vertices: must be a simple polygon (holes inside it, apart): the "
     "outline crosses or touches itself (edges from vertex 0 and vertex 2): a polygon must be "
     "simple"},
    {"RepeatedVertex",
     valid("obstacles: [{name: a, kind: island, vertices: [[1.6, 0], [1.7, 0], [1.7, 0], "
           "[1.8, 0.1]]}]\n"),
     "t.yaml:6: obstacles[0].vertices: must be a simple polygon (holes inside it, apart): the "
     "outline, vertex 2: repeats the vertex before it"},
    {"HoleOutsidePolygon",
     valid("obstacles: [{name: a, kind: island, vertices: [[1.6, 0], [1.9, 0], [1.9, 0.3]], "
           "holes: [[[1.0, 1.0], [1.1, 1.0], [1.1, 1.1]]]}]\n"),
     "t.yaml:6: obstacles[0].holes: must be a simple polygon (holes inside it, apart): hole 0 lies "
     "outside the outline"},
    {"HolesWithoutVertices",
     valid("obstacles: [{name: a, kind: box, center: [1, 1], size: [1, 1], holes: []}]\n"),
     "t.yaml:6: obstacles[0].holes: holes belong to a polygon (vertices)"},
    {"VertexNotAPair",
     valid("obstacles: [{name: a, kind: island, vertices: [[1.6, 0], [1.7], [1.8, 0.1]]}]\n"),
     "t.yaml:6: obstacles[0].vertices[1]: must be a list [x, y] of 2 numbers, got a list of 1"},
    {"ParkedVanOverhangBeyondItsLength",
     valid("parked_robots: [{name: van, pose: [1.8, 0.2, 0], length: 0.1, front_overhang: 0.2}]\n"),
     "t.yaml:6: parked_robots[0].front_overhang: must not exceed the vehicle's length (0.1), got "
     "0.2"},
    {"ZeroParkedMass", valid("parked_robots: [{name: van, pose: [1.8, 0.2, 0], mass_kg: 0}]\n"),
     "t.yaml:6: parked_robots[0].mass_kg: must be positive, got 0"},
    {"GroundClearanceAboveHeight", valid("robot: {height: 0.05, ground_clearance: 0.05}\n"),
     "t.yaml:6: robot.ground_clearance: must be below robot.height (0.05), got 0.05"},
    {"MergeOfAScalar", valid("robot: {<<: 3}\n"),
     "t.yaml:6: robot.<<: a merge key takes a map or a list of maps"},

    // The one placement rule (0.5 mm from obstacles and the lot edge).
    {"StartWithinTheMargin",
     // The footprint's front edge is at x = 0.51; the box starts 0.3 mm further.
     valid("obstacles: [{name: near, kind: box, center: [0.6103, 0.5], size: [0.2, 0.2]}]\n"),
     "t.yaml:4: start: robot footprint is 0.3 mm from obstacle \"near\"; start and goal keep at "
     "least the 0.5 mm margin of the planner's motion checks"},
    {"BumperOnTheWallFace",
     valid("robot: {length: 0.5, width: 0.25, front_overhang: 0.125}\n"
           "obstacles: [{name: wall, kind: wall, center: [0.75, 0.5], size: [0.25, 0.25]}]\n"),
     "t.yaml:4: start: robot footprint is 0 mm from obstacle \"wall\"; start and goal keep at "
     "least the 2.941 mm margin of the planner's motion checks"},
    {"GoalOnTheLotEdge", head("start: [0.5, 0.5, 0]\ngoal: {pose: [2, 1.5, 90]}\n"),
     "t.yaml:5: goal.pose: reference point (2, 1.5) is closer than the 0.5 mm margin to the lot "
     "edge [0, 2] x [0, 2]"},
    {"StartOverlapsABollard",
     valid("obstacles: [{name: post, kind: bollard, center: [0.52, 0.5], radius: 0.02}]\n"),
     "t.yaml:4: start: robot footprint overlaps obstacle \"post\""},
    {"GoalOverlapsAnIsland",
     valid("obstacles: [{name: isle, kind: island, vertices: [[1.5, 1.45], [1.6, 1.6], "
           "[1.4, 1.6]]}]\n"),
     "t.yaml:5: goal.pose: robot footprint overlaps obstacle \"isle\""},
};

INSTANTIATE_TEST_SUITE_P(ScenarioReader, RejectsBadInput, ::testing::ValuesIn(kBadCases),
                         [](const ::testing::TestParamInfo<BadCase>& param_info) {
                           return std::string(param_info.param.name);
                         });

TEST(ScenarioReader, AnyPolygonWithHolesIsCutIntoConvexPartsExactly) {
  // An L-shaped kerb, and a square island with a square hole, both clockwise.
  const Scenario s = parseScenario(
      valid("obstacles:\n"
            "  - {name: l, kind: curb, vertices: [[1.6, 0], [1.6, 0.3], [1.7, 0.3], [1.7, 0.1], "
            "[1.9, 0.1], [1.9, 0]]}\n"
            "  - name: ring\n    kind: island\n    height: 0.2\n"
            "    vertices: [[1.0, 0.8], [1.0, 1.1], [1.3, 1.1], [1.3, 0.8]]\n"
            "    holes: [[[1.1, 0.9], [1.1, 1.0], [1.2, 1.0], [1.2, 0.9]]]\n"),
      "t.yaml");
  const Obstacle& l = s.obstacles[0];
  ASSERT_EQ(l.shape, ObstacleShape::kCompound);
  EXPECT_EQ(l.compound->parts.size(), 2u);
  EXPECT_EQ(l.compound->rings.size(), 1u);
  const Obstacle& ring = s.obstacles[1];
  ASSERT_EQ(ring.shape, ObstacleShape::kCompound);
  EXPECT_EQ(ring.height_m, 0.2);
  EXPECT_EQ(ring.compound->rings.size(), 2u);
  double area = 0.0;
  for (const auto& part : ring.compound->parts) area += 0.5 * signedDoubleArea(part);
  EXPECT_NEAR(area, 0.09 - 0.01, 1e-12);
  // The footprint fits in the hole, and touches the ring once it moves.
  const RobotDef robot;
  EXPECT_GT(separation(footprintAt(robot, {1.175, 0.95, 0.0}), ring), 0.0);
  EXPECT_LT(separation(footprintAt(robot, {1.195, 0.95, 0.0}), ring), 0.0);
  // Convex polygons stay as they were.
  EXPECT_EQ(parseScenario(valid("obstacles: [{name: t, kind: island, vertices: [[1.6, 0], [1.9, "
                                "0], [1.9, 0.3]]}]\n"),
                          "t.yaml")
                .obstacles[0]
                .shape,
            ObstacleShape::kPolygon);
}

}  // namespace scenario_reader_test
}  // namespace parksim
