// Overrides replace fields of the parsed document and are then validated like the file.

#include "parksim/scenario/world/ScenarioOverrides.h"

#include <string>

#include <gtest/gtest.h>

#include "parksim/core/geometry/Angle.h"
#include "parksim/core/io/Error.h"
#include "parksim/scenario/world/ScenarioReader.h"
#include "tests/support/TestPaths.h"

namespace parksim {
// Named, not anonymous: its program is compiled as one unity batch, where another file's
// helpers of the same names would meet these.
namespace scenario_overrides_test {

const std::string kWorld = parksim::testing::sourceDir() + "/worlds/head_in.yaml";

std::string errorOf(const std::vector<ScenarioOverride>& overrides) {
  try {
    loadScenario(kWorld, overrides);
  } catch (const Error& e) {
    return e.what();
  }
  return "no error";
}

TEST(ScenarioOverrides, ReplaceFieldsAndCreateMissingSections) {
  const Scenario file = loadScenario(kWorld);
  const Scenario s = loadScenario(
      kWorld, {{"start", "[0.2, 0.15, 45]", "--start"},
               {"goal.pose", "[1.5, 0.05, -90]", "--goal"},
               {"robot.wheel_radius", "0.025", "--set robot.wheel_radius=0.025"},
               {"obstacles[0].center", "[0.9, 0.6]", "--set obstacles[0].center=[0.9, 0.6]"},
               {"physics.time_step_s", "0.002", "--set physics.time_step_s=0.002"}});
  EXPECT_EQ(s.start.x, 0.2);
  EXPECT_EQ(s.start.theta, degToRad(45.0));
  EXPECT_EQ(s.goal.pose.y, 0.05);
  EXPECT_EQ(s.robot.wheel_radius_m, 0.025);
  EXPECT_EQ(s.obstacles[0].box.center.x(), 0.9);
  EXPECT_EQ(s.physics.time_step_s, 0.002);
  // Everything else is the file's.
  EXPECT_EQ(s.name, file.name);
  EXPECT_EQ(s.robot.wheel_base_m, file.robot.wheel_base_m);
  EXPECT_EQ(s.obstacles.size(), file.obstacles.size());
  EXPECT_EQ(s.source_path, kWorld);
}

TEST(ScenarioOverrides, BadValuesGetTheFilesChecksAndNameTheOverride) {
  EXPECT_EQ(errorOf({{"robot.wheel_radius", "-1", "--set robot.wheel_radius=-1"}}),
            "--set robot.wheel_radius=-1: robot.wheel_radius: must be positive, got -1");
  EXPECT_EQ(errorOf({{"start", "[0.3, 0.6]", "--start 0.3,0.6"}})
                .rfind("--start 0.3,0.6: start: must be a list [x, y, yaw_deg] of 3 numbers", 0),
            0u);
  EXPECT_EQ(errorOf({{"robot.bogus", "1", "--set robot.bogus=1"}})
                .rfind("--set robot.bogus=1: "
                       "robot.bogus: unknown field",
                       0),
            0u);
  EXPECT_EQ(errorOf({{"obstacles[99].center", "[1, 1]", "L"}}),
            "L: obstacles[99]: obstacles has 3 items");
  EXPECT_EQ(errorOf({{"name.first", "x", "L"}}), "L: name: is not a map");
  EXPECT_EQ(errorOf({{"robot..x", "1", "L"}}), "L: bad field path 'robot..x': empty key");
  // A stray ']' was read as a key "]" and blamed on the file's line as an unknown field.
  EXPECT_EQ(errorOf({{"obstacles[1]].x", "1", "L"}}),
            "L: bad field path 'obstacles[1]].x': ']' without '['");
  EXPECT_EQ(errorOf({{"name", "[1", "L"}}).rfind("L: (syntax): ", 0), 0u);
  // A problem the override causes elsewhere is reported where it shows, with the file's line:
  // an obstacle moved onto the start makes the (unchanged) start entry fail.
  const std::string other = errorOf({{"obstacles[0].center", "[0.1, 0.1]", "L"}});
  EXPECT_EQ(other.rfind(kWorld + ":", 0), 0u) << other;
  EXPECT_NE(other.find(": start: "), std::string::npos) << other;
}

}  // namespace scenario_overrides_test
}  // namespace parksim
