// A world file read once, whole: the scenario and its realism: and tolerance: sections, with
// overrides applied to every part of the file.

#include "parksim/scenario/World.h"

#include <string>
#include <string_view>

#include <gtest/gtest.h>

#include "parksim/core/Error.h"
#include "parksim/scenario/ScenarioReader.h"

namespace parksim {
namespace {

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

}  // namespace
}  // namespace parksim
