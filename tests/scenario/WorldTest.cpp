// A world file read once, whole: the scenario and its realism: and tolerance: sections, with
// overrides applied to every part of the file.

#include "parksim/scenario/world/World.h"

#include <string>
#include <string_view>
#include <vector>

#include <gtest/gtest.h>

#include "parksim/core/io/Error.h"
#include "parksim/scenario/world/ScenarioReader.h"

namespace parksim {
// Named, not anonymous: its program is compiled as one unity batch, where another file's
// helpers of the same names would meet these.
namespace world_test {

constexpr std::string_view kWorld =
    "format: parksim-world/1\n"
    "name: t\n"
    "lot: {x_min: 0, y_min: 0, x_max: 2, y_max: 2}\n"
    "start: [0.5, 0.5, 0]\n"
    "goal: {pose: [1.5, 1.5, 90]}\n"
    "tolerance: {max_contacts: 3}\n";

TEST(World, HoldsTheScenarioAndTheSectionsOfOneRead) {
  const World w = parseWorld(kWorld, "t.yaml");
  EXPECT_EQ(w.scenario.name, "t");
  EXPECT_EQ(w.scenario.source_path, "t.yaml");
  EXPECT_FALSE(w.sections.has_realism);
  EXPECT_TRUE(w.sections.has_tolerance);
  EXPECT_EQ(w.sections.tolerance.max_contacts, 3);
  // The scenario is the one parseScenario reads.
  EXPECT_EQ(parseScenario(kWorld, "t.yaml").start, w.scenario.start);
}

TEST(World, OverridesReachTheRealismAndToleranceSections) {
  const World w = parseWorld(kWorld, "t.yaml",
                             {{"realism.preset", "lab", "--set realism.preset=lab"},
                              {"tolerance.max_contacts", "7", "--set tolerance.max_contacts=7"},
                              {"start", "[0.4, 0.5, 0]", "--start 0.4,0.5,0"}});
  EXPECT_TRUE(w.sections.has_realism);
  EXPECT_EQ(w.sections.realism.name, "lab");
  EXPECT_EQ(w.sections.tolerance.max_contacts, 7);
  EXPECT_EQ(w.scenario.start.x, 0.4);
}

TEST(World, AnOverriddenFieldIsNamedByItsOverride) {
  try {
    (void)parseWorld(kWorld, "t.yaml",
                     {{"tolerance.max_contacts", "-1", "--set tolerance.max_contacts=-1"}});
    FAIL() << "accepted";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()).rfind("--set tolerance.max_contacts=-1: ", 0), 0u) << e.what();
  }
}

// A world file parsed once and read many times (a sweep's set: values) reads exactly as
// parseWorld with the same overrides: the same world, the same hash, the same messages; reads
// with the same paths change values in place, others start from the file again.
TEST(WorldFile, ReadsAsParseWorldWhateverTheOrderOfReads) {
  const std::string text = std::string(kWorld) + "robot: {wheel_radius: 0.02}\n";
  WorldFile file(text, "t.yaml");
  using Overrides = std::vector<ScenarioOverride>;
  const auto o = [](const std::string& path, const std::string& value) {
    return ScenarioOverride{path, value, "set: " + path + "=" + value};
  };
  const std::vector<Overrides> reads = {
      {},
      {o("robot.wheel_radius", "0.025"), o("tolerance.max_contacts", "5")},
      {o("robot.wheel_radius", "0.03"), o("tolerance.max_contacts", "6")},   // in place
      {o("robot.wheel_radius", "-1"), o("tolerance.max_contacts", "6")},     // refused
      {o("robot.wheel_radius", "0.021"), o("tolerance.max_contacts", "2")},  // after a refusal
      {o("robot.max_wheel_speed_radps", "7")},                               // other paths
      {o("robot.max_wheel_speed_radps", "\"7\"")},  // quoted: not a number, as in a file
      {o("robot.max_wheel_speed_radps", "[7]")},
      {o("robot.max_wheel_speed_radps", "8")},
      {o("robot.max_wheel_speed_radps", "9e0")},
      {o("robot.max_wheel_speed_radps", "nine")},
      {o("robot.max_wheel_speed_radps", "- 9")},  // a list, parsed
      {o("robot.max_wheel_speed_radps", "+9.5")},
      {},
  };
  for (const Overrides& overrides : reads) {
    std::string expected_error;
    World expected;
    try {
      expected = parseWorld(text, "t.yaml", overrides);
    } catch (const Error& e) {
      expected_error = e.what();
    }
    std::string error;
    World got;
    try {
      got = file.read(overrides);
    } catch (const Error& e) {
      error = e.what();
    }
    const std::string what = overrides.empty() ? "(none)" : overrides.front().label;
    EXPECT_EQ(error, expected_error) << what;
    if (!error.empty()) continue;
    EXPECT_EQ(got.content_hash, expected.content_hash) << what;
    EXPECT_EQ(got.scenario.robot.wheel_radius_m, expected.scenario.robot.wheel_radius_m) << what;
    EXPECT_EQ(got.scenario.robot.max_wheel_speed_radps,
              expected.scenario.robot.max_wheel_speed_radps)
        << what;
    EXPECT_EQ(got.sections.tolerance.max_contacts, expected.sections.tolerance.max_contacts)
        << what;
  }
  // A copy reads alike and shares nothing with the original.
  const WorldFile copy(file);
  EXPECT_EQ(copy.read({o("robot.wheel_radius", "0.026")}).scenario.robot.wheel_radius_m, 0.026);
  EXPECT_EQ(file.read().scenario.robot.wheel_radius_m, 0.02);
}

}  // namespace world_test
}  // namespace parksim
