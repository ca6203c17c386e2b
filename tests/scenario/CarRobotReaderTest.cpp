// A world's `robot: {drive: car}` (docs/cars.md, docs/world-format.md): the mid-size car's
// defaults, each key overriding its field, the rear wheels' limits following from the car's,
// and every refusal naming the file, the line and the field.

#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "parksim/core/geometry/Angle.h"
#include "parksim/core/io/Error.h"
#include "parksim/core/model/Geometry.h"
#include "parksim/scenario/world/ScenarioOverrides.h"
#include "parksim/scenario/world/ScenarioReader.h"

namespace parksim {
namespace {

// A 30 m lot; the robot section is line 6.
std::string world(const std::string& robot) {
  return "format: parksim-world/1\nname: t\nlot: {x_min: 0, y_min: 0, x_max: 30, y_max: 30}\n"
         "start: [5, 5, 0]\ngoal: {pose: [20, 20, 90]}\n" +
         robot;
}

std::string errorOf(const std::string& yaml) {
  try {
    parseScenario(yaml, "t.yaml");
  } catch (const Error& e) {
    return e.what();
  }
  return "(accepted)";
}

TEST(CarRobotReader, DriveCarAloneIsTheMidSizeCar) {
  const RobotDef r = parseScenario(world("robot: {drive: car}\n"), "t.yaml").robot;
  const RobotDef car = midSizeCar();
  EXPECT_TRUE(r.isCar());
  EXPECT_EQ(r.length_m, 4.689);
  EXPECT_EQ(r.width_m, 1.942);
  EXPECT_EQ(r.front_overhang_m, car.front_overhang_m);
  EXPECT_EQ(r.axle_distance_m, 2.8);
  EXPECT_EQ(r.wheel_base_m, car.wheel_base_m);
  EXPECT_EQ(r.wheel_radius_m, car.wheel_radius_m);
  EXPECT_EQ(r.max_steer_rad, 0.75);
  EXPECT_EQ(r.max_steer_rate_radps, 0.5);
  EXPECT_EQ(r.max_speed_mps, 2.5);
  EXPECT_EQ(r.max_accel_mps2, 1.0);
  EXPECT_EQ(r.max_wheel_speed_radps, car.max_wheel_speed_radps);
  EXPECT_EQ(r.max_wheel_accel_radps2, car.max_wheel_accel_radps2);
  EXPECT_EQ(r.height_m, car.height_m);
  EXPECT_EQ(r.ground_clearance_m, car.ground_clearance_m);
  // The tightest turn of the benchmarks' car: 2.8 / tan(0.75) = 3.006 m.
  EXPECT_NEAR(r.minTurningRadius(), 3.006, 5e-4);
}

TEST(CarRobotReader, DifferentialIsTheDefaultAndTheStudysRobot) {
  const RobotDef none = parseScenario(world(""), "t.yaml").robot;
  const RobotDef said = parseScenario(world("robot: {drive: differential}\n"), "t.yaml").robot;
  EXPECT_FALSE(said.isCar());
  EXPECT_EQ(none.drive, Drive::kDifferential);
  EXPECT_EQ(said.length_m, none.length_m);
  EXPECT_EQ(said.wheel_base_m, none.wheel_base_m);
  EXPECT_EQ(said.max_wheel_speed_radps, none.max_wheel_speed_radps);
}

TEST(CarRobotReader, EveryCarKeyOverridesItsField) {
  const RobotDef r = parseScenario(world("robot:\n"
                                         "  drive: car\n"
                                         "  length: 4.2\n"
                                         "  width: 1.8\n"
                                         "  front_overhang: 3.3\n"
                                         "  axle_distance: 2.5\n"
                                         "  track: 1.5\n"
                                         "  wheel_radius: 0.3\n"
                                         "  max_steer_deg: 35\n"
                                         "  max_steer_rate_degps: 20\n"
                                         "  max_speed_mps: 3\n"
                                         "  max_accel_mps2: 1.5\n"
                                         "  height: 1.4\n"
                                         "  ground_clearance: 0.12\n"),
                                   "t.yaml")
                         .robot;
  EXPECT_EQ(r.length_m, 4.2);
  EXPECT_EQ(r.width_m, 1.8);
  EXPECT_EQ(r.front_overhang_m, 3.3);
  EXPECT_EQ(r.axle_distance_m, 2.5);
  EXPECT_EQ(r.wheel_base_m, 1.5);
  EXPECT_EQ(r.wheel_radius_m, 0.3);
  EXPECT_EQ(r.max_steer_rad, degToRad(35.0));
  EXPECT_EQ(r.max_steer_rate_radps, degToRad(20.0));
  EXPECT_EQ(r.max_speed_mps, 3.0);
  EXPECT_EQ(r.max_accel_mps2, 1.5);
  EXPECT_EQ(r.height_m, 1.4);
  EXPECT_EQ(r.ground_clearance_m, 0.12);
  // The rear wheels' limits follow: the outer wheel at top speed on the tightest turn, and the
  // car's acceleration at the wheel's radius.
  const double kappa = std::tan(degToRad(35.0)) / 2.5;
  EXPECT_DOUBLE_EQ(r.max_wheel_speed_radps, 3.0 * (1.0 + 0.75 * kappa) / 0.3);
  EXPECT_DOUBLE_EQ(r.max_wheel_accel_radps2, 1.5 / 0.3);
  EXPECT_DOUBLE_EQ(r.topSpeed(), 3.0);
}

TEST(CarRobotReader, RefusalsNameFileLineAndField) {
  // A turning radius smaller than half the track: 0.5 / tan(60 deg) = 0.29 m < 1.9 / 2, where
  // the inner rear wheel would roll backwards.
  const std::string tight =
      errorOf(world("robot:\n  drive: car\n  track: 1.9\n"
                    "  axle_distance: 0.5\n  max_steer_deg: 60\n"));
  EXPECT_EQ(tight.rfind("t.yaml:10: robot.max_steer_deg: the tightest turning radius", 0), 0u)
      << tight;
  EXPECT_NE(tight.find("smaller than half the track (0.95 m)"), std::string::npos) << tight;
  // The same with only the axle given names the axle.
  EXPECT_EQ(errorOf(world("robot: {drive: car, axle_distance: 0.3}\n"))
                .rfind("t.yaml:6: robot.axle_distance: the tightest turning radius", 0),
            0u);
  EXPECT_EQ(errorOf(world("robot: {drive: car, axle_distance: 4}\n")),
            "t.yaml:6: robot.axle_distance: must not exceed robot.front_overhang (3.739) (the "
            "front axle must lie within the body), got 4");
  EXPECT_EQ(errorOf(world("robot: {drive: car, front_overhang: 2}\n")),
            "t.yaml:6: robot.front_overhang: must be at least robot.axle_distance (2.8) (the "
            "front axle must lie within the body), got 2");
  EXPECT_EQ(errorOf(world("robot: {drive: car, track: 2}\n")),
            "t.yaml:6: robot.track: must not exceed robot.width (1.942) (the wheels must lie "
            "within the body, which alone meets obstacles), got 2");
  EXPECT_EQ(errorOf(world("robot: {drive: car, max_steer_deg: 90}\n"))
                .rfind("t.yaml:6: robot.max_steer_deg: must be in [0.5, 80] degrees (", 0),
            0u);
  EXPECT_EQ(errorOf(world("robot: {drive: car, max_speed_mps: -1}\n")),
            "t.yaml:6: robot.max_speed_mps: must be positive, got -1");
  EXPECT_EQ(errorOf(world("robot: {drive: truck}\n")),
            "t.yaml:6: robot.drive: unknown drive \"truck\"; expected one of: differential, car");
  // One drive's keys on the other are refused by name, not as unknown fields.
  EXPECT_EQ(errorOf(world("robot:\n  length: 0.1\n  max_steer_deg: 30\n")),
            "t.yaml:8: robot.max_steer_deg: a car's key: this robot is a differential drive "
            "(robot.drive: car makes a car, docs/cars.md)");
  EXPECT_EQ(errorOf(world("robot: {drive: car, wheel_base: 1.6}\n"))
                .rfind("t.yaml:6: robot.wheel_base: a differential drive's key: a car", 0),
            0u);
  EXPECT_EQ(errorOf(world("robot: {drive: car, max_wheel_speed_radps: 9}\n"))
                .rfind("t.yaml:6: robot.max_wheel_speed_radps: a differential drive's key", 0),
            0u);
  EXPECT_EQ(errorOf(world("robot: {drive: car, steer: 1}\n"))
                .rfind("t.yaml:6: robot.steer: unknown field; expected one of: drive, length", 0),
            0u);
}

TEST(CarRobotReader, ParkedVehiclesAreTheCarsFootprintAtTheirRearAxle) {
  const Scenario s = parseScenario(
      world("robot: {drive: car}\nparked_robots: [{name: p, pose: [10, 10, 90]}]\n"), "t.yaml");
  ASSERT_EQ(s.obstacles.size(), 1u);
  const OrientedBox box = s.obstacles[0].box;
  // Facing +y with its rear axle's middle at (10, 10): the body spans y from 10 - 0.95 to
  // 10 + 3.739 and x 10 +- 0.971.
  const double rear = 4.689 - 3.739;
  EXPECT_NEAR(box.center.x(), 10.0, 1e-12);
  EXPECT_NEAR(box.center.y(), 10.0 + 0.5 * (3.739 - rear), 1e-12);
  EXPECT_NEAR(std::abs(std::sin(box.yaw)), 1.0, 1e-12);
  EXPECT_NEAR(box.half_extents.x(), 0.5 * 4.689, 1e-12);
  EXPECT_NEAR(box.half_extents.y(), 0.5 * 1.942, 1e-12);
}

TEST(CarRobotReader, CommandLineAndSweepPathsSetACarsKeys) {
  const std::string yaml = world("robot: {drive: car}\n");
  const Scenario s = parseScenario(yaml, "t.yaml",
                                   {{"robot.max_steer_deg", "30", "--set robot.max_steer_deg=30"},
                                    {"robot.max_speed_mps", "2", "--set robot.max_speed_mps=2"}});
  EXPECT_EQ(s.robot.max_steer_rad, degToRad(30.0));
  EXPECT_EQ(s.robot.max_speed_mps, 2.0);
  // A car made on the command line from a differential world.
  EXPECT_TRUE(parseScenario(world(""), "t.yaml", {{"robot.drive", "car", "--set robot.drive=car"}})
                  .robot.isCar());
  try {
    parseScenario(yaml, "t.yaml", {{"robot.max_steer_deg", "85", "--set robot.max_steer_deg=85"}});
    FAIL() << "accepted";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()).rfind(
                  "--set robot.max_steer_deg=85: robot.max_steer_deg: must be in [0.5, 80]", 0),
              0u)
        << e.what();
  }
}

}  // namespace
}  // namespace parksim
