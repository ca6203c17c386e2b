// The physical ranges of robot and physics values (issue 22, item 4; docs/limits.md): the
// degenerate values the issue found (a 1e-12 m wheel base, a 1e-300 kg chassis, a 1000 s time
// step, a 1e-300 rad/s wheel speed, a 5 x 5 m body on an 85 mm wheel base) are refused when the
// world is read, each naming its field and the reason; every shipped world and real robots from
// 1 cm to 10 m stay valid.

#include "parksim/scenario/world/PhysicalRanges.h"

#include <cstdio>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "parksim/core/io/Error.h"
#include "parksim/scenario/world/World.h"
#include "tests/support/TestPaths.h"

namespace parksim {
// Named, not anonymous: its program is compiled as one unity batch, where another file's
// helpers of the same names would meet these.
namespace physical_ranges_test {

namespace fs = std::filesystem;

// A 2 m lot with the robot in its middle; `extra` adds sections (line 6 on).
std::string world(const std::string& extra) {
  return "format: parksim-world/1\nname: t\nlot: {x_min: 0, y_min: 0, x_max: 2, y_max: 2}\n"
         "start: [0.5, 0.5, 0]\ngoal: {pose: [0.7, 0.5, 0]}\n" +
         extra;
}

// A value as YAML: whole numbers without a fraction (solver_iterations is an integer).
std::string yamlNumber(double v) {
  char text[64];
  std::snprintf(text, sizeof text,
                v == static_cast<double>(static_cast<long long>(v)) ? "%.0f" : "%.17g", v);
  return text;
}

std::string errorOf(const std::string& yaml) {
  try {
    parseWorld(yaml, "t.yaml");
  } catch (const Error& e) {
    return e.what();
  }
  return "(accepted)";
}

TEST(PhysicalRanges, TheIssuesDegenerateWorldsAreRefusedNamingTheFieldAndWhy) {
  EXPECT_EQ(errorOf(world("robot: {wheel_base: 1e-12}\n")),
            "t.yaml:6: robot.wheel_base: must be in [0.005, 20] m (a track from a micro robot's "
            "5 mm to a 20 m vehicle's), got 1e-12 (docs/limits.md)");
  EXPECT_EQ(errorOf(world("physics: {chassis_mass_kg: 1e-300}\n")),
            "t.yaml:6: physics.chassis_mass_kg: must be in [0.001, 100000] kg (from a 1 g micro "
            "robot to a 100 t vehicle), got 1e-300 (docs/limits.md)");
  // The upper bound of the time step, with its reason.
  EXPECT_EQ(errorOf(world("physics: {time_step_s: 1000}\n")),
            "t.yaml:6: physics.time_step_s: must be in [1e-05, 0.01] s (each 0.1 s control "
            "period of a plan is followed over at least 10 physics steps, and the realism's "
            "100 Hz pose sensor takes one sample per step at most; below 10 us the limit of 1e6 "
            "steps leaves 10 s of simulated time), got 1000 (docs/limits.md)");
  EXPECT_EQ(errorOf(world("physics: {time_step_s: 0.01}\n")), "(accepted)");
  EXPECT_NE(errorOf(world("physics: {time_step_s: 0.0101}\n")), "(accepted)");
  // A wheel speed of 1e-300 rad/s names the wheel speed (it named the lot's diagonal and the
  // wheel radius: the steering's period limit was the first to notice).
  const std::string speed = errorOf(world("robot: {max_wheel_speed_radps: 1e-300}\n"));
  EXPECT_EQ(speed.rfind("t.yaml:6: robot.max_wheel_speed_radps: must be in [0.1, 1000] rad/s (", 0),
            0u)
      << speed;
  EXPECT_NE(speed.find("got 1e-300"), std::string::npos);
  // Signs keep the readers' own message.
  EXPECT_EQ(errorOf(world("robot: {wheel_radius: -1}\n")),
            "t.yaml:6: robot.wheel_radius: must be positive, got -1");
}

// A car's own keys, which a differential drive refuses (docs/cars.md).
bool isCarKey(const std::string& key) {
  for (const char* k :
       {"robot.track", "robot.axle_distance", "robot.max_steer_deg", "robot.max_steer_rate_degps",
        "robot.max_speed_mps", "robot.max_accel_mps2"}) {
    if (key == k) return true;
  }
  return false;
}

TEST(PhysicalRanges, EveryRangeAcceptsItsBoundsAndRefusesBeyondThem) {
  for (const ParameterRange& r : physicalRanges()) {
    const std::string key(r.key);
    const std::string section =
        key.substr(0, key.find('.')) + ": {" + (isCarKey(key) ? "drive: car, " : "");
    const std::string field = key.substr(key.find('.') + 1);
    if (key.rfind("parked_robots", 0) == 0) continue;  // a list entry: below
    for (const double v : {r.lo, r.hi}) {
      const std::string text = world(section + field + ": " + yamlNumber(v) + "}\n");
      // Bounds alone may not make a drivable robot (a 20 m body on the default wheels): only
      // the range's own message must not appear.
      EXPECT_EQ(errorOf(text).find("must be in ["), std::string::npos) << key << " = " << v;
    }
    const double above = r.hi * 1.5;
    EXPECT_NE(errorOf(world(section + field + ": " + yamlNumber(above) + "}\n"))
                  .find(key + ": must be in ["),
              std::string::npos)
        << key;
    if (r.lo > 0.0 && field != "solver_iterations") {  // below 1 iteration: not positive
      EXPECT_NE(errorOf(world(section + field + ": " + yamlNumber(r.lo * 0.5) + "}\n"))
                    .find(key + ": must be in ["),
                std::string::npos)
          << key;
    }
  }
  EXPECT_NE(errorOf(world("parked_robots: [{name: p, pose: [1.5, 1.5, 0], mass_kg: 1e6}]\n"))
                .find("parked_robots[0].mass_kg: must be in [0.001, 100000] kg"),
            std::string::npos);
}

// The issue's 5 x 5 m body on the study's 85 mm wheel base planned exactly, then ended 1 m
// and 139 degrees off: its wheels cannot grip hard enough to turn it as its limits ask.
TEST(PhysicalRanges, ABodyItsWheelsCannotTurnIsRefused) {
  const std::string big = errorOf(world("robot: {length: 5, width: 5}\n"));
  EXPECT_EQ(big.rfind("t.yaml:6: robot: turning a 5 x 5 m body on a 0.085 m wheel base at the "
                      "wheel acceleration limit (40 rad/s^2) needs ",
                      0),
            0u)
      << big;
  EXPECT_NE(big.find("widen robot.wheel_base, or lower robot.max_wheel_accel_radps2"),
            std::string::npos);
  // The numbers behind it: ~460 N of grip asked of wheels that give ~1.2 N.
  RobotDef body;
  body.length_m = body.width_m = 5.0;
  const WheelDemand w = wheelDemand(body, PhysicsDef{});
  EXPECT_NEAR(w.turn_n, 460.0, 10.0);
  EXPECT_NEAR(w.grip_n, 0.5 * 0.24 * 9.81, 1e-12);
  // The study's robot has about ten times the grip it needs, and twenty times the torque.
  const WheelDemand study = wheelDemand(RobotDef{}, PhysicsDef{});
  EXPECT_GT(study.grip_n / study.force_n(), 10.0);
  EXPECT_GT(PhysicsDef{}.max_wheel_torque_nm / (study.force_n() * RobotDef{}.wheel_radius_m), 20.0);
  // kGripMargin, from the simulation: a 0.6 m square body (2.3 times the grip) still parked
  // within 1 mm and is accepted; a 1 m one (6.3 times) ended 151 mm off and is refused.
  EXPECT_EQ(errorOf(world("robot: {length: 0.6, width: 0.6, front_overhang: 0.3}\n")),
            "(accepted)");
  EXPECT_NE(errorOf(world("robot: {length: 1, width: 1, front_overhang: 0.5}\n"))
                .find("robot: turning a 1 x 1 m body on a 0.085 m wheel base"),
            std::string::npos);
  // Straight-ahead acceleration beyond the grip, and torque below what the grip allows.
  EXPECT_NE(errorOf(world("robot: {width: 0.3, wheel_base: 0.3, max_wheel_accel_radps2: 5000}\n"))
                .find("accelerating the robot straight ahead"),
            std::string::npos);
  EXPECT_NE(
      errorOf(world("physics: {max_wheel_torque_nm: 1e-4}\n"))
          .find("t.yaml:6: physics: turning a 0.08 x 0.085 m body on a 0.085 m wheel base at the "
                "wheel acceleration limit (40 rad/s^2) needs 0.00212 N m at each wheel, "
                "more than physics.max_wheel_torque_nm (0.0001)"),
      std::string::npos);
  EXPECT_NE(errorOf(world("physics: {wheel_friction: 0}\n"))
                .find("more than 2.5 times their grip (0 N: wheel_friction x ground_friction"),
            std::string::npos);
}

// A wheel beyond the body's sides: the planner checks the body only and the simulated wheels
// touch only the ground, so it would drive through walls unseen. Equal is the study's robot.
TEST(PhysicalRanges, WheelsOutsideTheBodyAreRefused) {
  EXPECT_EQ(errorOf(world("robot: {wheel_base: 20}\n")),
            "t.yaml:6: robot.wheel_base: must not exceed robot.width (0.085) (the wheels must "
            "lie within the body, which alone meets obstacles), got 20");
  // Narrowing the body under the default wheels names the width, the field that was given.
  EXPECT_EQ(errorOf(world("robot: {width: 0.05}\n")),
            "t.yaml:6: robot.width: must be at least robot.wheel_base (0.085) (the wheels must "
            "lie within the body, which alone meets obstacles), got 0.05");
  EXPECT_EQ(errorOf(world("robot: {wheel_base: 0.0851}\n")).find("must not exceed robot.width"),
            std::string("t.yaml:6: robot.wheel_base: ").size());
  EXPECT_EQ(errorOf(world("robot: {width: 0.2, wheel_base: 0.2}\n")), "(accepted)");
  EXPECT_EQ(errorOf(world("robot: {wheel_base: 0.085}\n")), "(accepted)");
}

// Robots from 1 cm to 10 m, with their own masses, motors and wheels (a micro robot, the
// e-puck, a TurtleBot3 Burger, a 10 m vehicle): all valid, the micro robot but for its wheels,
// too light for Bullet to turn (below).
TEST(PhysicalRanges, RealRobotsFromOneCentimetreToTenMetresAreValid) {
  const std::string micro =
      // 1 cm micro robot: 2 mm wheels, 1 g.
      "robot: {length: 0.01, width: 0.01, front_overhang: 0.005, wheel_base: 0.008, "
      "wheel_radius: 0.002, max_wheel_speed_radps: 20, max_wheel_accel_radps2: 100, height: "
      "0.005, ground_clearance: 0.0005}\nphysics: {chassis_mass_kg: 0.001, wheel_mass_kg: "
      "0.0001, max_wheel_torque_nm: 1e-5}\n";
  // Its 0.1 g wheels' axle inertia, 2/5 m r^2, is below Bullet's single-precision epsilon, under
  // which a joint never turns: refused when the world is read, with the mass it would need.
  const double inertia = 0.4 * 1e-4 * 0.002 * 0.002;
  EXPECT_LT(inertia, 1.1920929e-7);
  EXPECT_EQ(errorOf(world(micro)),
            "t.yaml:6: robot: a wheel's inertia about its axis, 1.6e-10 kg m^2 "
            "(physics.wheel_mass_kg 0.0001 kg at robot.wheel_radius 0.002 m), is below Bullet's "
            "1.19e-07 kg m^2, under which a joint never turns: at this radius a wheel needs "
            "0.0745 kg or more (docs/limits.md)");
  const char* robots[] = {
      // e-puck: 75 mm round (as a square), 53 mm track, 41 mm wheels, 150 g.
      "robot: {length: 0.075, width: 0.075, front_overhang: 0.0375, wheel_base: 0.053, "
      "wheel_radius: 0.0205, max_wheel_speed_radps: 6.28}\nphysics: {chassis_mass_kg: 0.15, "
      "wheel_mass_kg: 0.005}\n",
      // TurtleBot3 Burger: 138 x 178 mm, 160 mm track, 33 mm wheels, 1 kg, 1.5 N m servos.
      "robot: {length: 0.138, width: 0.178, front_overhang: 0.032, wheel_base: 0.16, "
      "wheel_radius: 0.033, max_wheel_speed_radps: 6.67, max_wheel_accel_radps2: 20, height: "
      "0.192}\nphysics: {chassis_mass_kg: 1.0, wheel_mass_kg: 0.03, max_wheel_torque_nm: 1.5}\n",
      // A 10 m vehicle: 4 m wide, 3.6 m track, 0.5 m wheels, 10 t, 20 kN m per wheel.
      "robot: {length: 10, width: 4, front_overhang: 5, wheel_base: 3.6, wheel_radius: 0.5, "
      "max_wheel_speed_radps: 4, max_wheel_accel_radps2: 2, height: 3, ground_clearance: "
      "0.3}\nphysics: {chassis_mass_kg: 10000, wheel_mass_kg: 200, max_wheel_torque_nm: "
      "20000}\n",
  };
  for (const char* robot : robots) EXPECT_EQ(errorOf(world(robot)), "(accepted)") << robot;
}

TEST(PhysicalRanges, EveryShippedWorldStaysValid) {
  const fs::path root = testing::sourceDir();
  int n = 0;
  for (const char* folder :
       {"worlds", "tests/pipeline/worlds", "tests/renders", "bench/scale", "tests/sweep/worlds"}) {
    if (!fs::is_directory(root / folder)) continue;
    for (const fs::directory_entry& e : fs::directory_iterator(root / folder)) {
      if (e.path().extension() != ".yaml") continue;
      EXPECT_NO_THROW(loadWorld(e.path().string())) << e.path();
      ++n;
    }
  }
  EXPECT_GE(n, 15);
}

}  // namespace physical_ranges_test
}  // namespace parksim
