#include "parksim/planner/steering/OmplPlugin.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "parksim/core/geometry/Angle.h"
#include "parksim/planner/steering/ReedsSheppSteering.h"
#include "tests/support/LoadedLibraries.h"

namespace parksim {
namespace {

using testing::mapped;

TEST(OmplPlugin, NamesOmplsPlannerStatuses) {
  const OmplPlugin ompl;
  // OMPL's StatusType: UNKNOWN = 0, ..., EXACT_SOLUTION = 6, CRASH = 7, ABORT = 8 (which
  // OMPL 1.5 names "Unknown status" too), TYPE_COUNT = 9.
  EXPECT_STREQ(ompl.api().status_name(0), "Unknown status");
  EXPECT_STREQ(ompl.api().status_name(6), "Exact solution");
  EXPECT_STREQ(ompl.api().status_name(7), "Crash");
  EXPECT_NE(ompl.api().status_name(8), nullptr);
  EXPECT_EQ(ompl.api().status_name(9), nullptr);
  EXPECT_EQ(ompl.api().status_name(-1), nullptr);
}

TEST(OmplPlugin, ReedsSheppPathsInRadii) {
  const OmplPlugin ompl;
  const ParksimOmplApi& api = ompl.api();
  void* space = api.reeds_shepp_new(0.5);
  int types[5];
  double lengths[5], total = 0.0;
  // 1 m straight back: one straight segment of -2 radii.
  const double from[3] = {1.0, 2.0, 0.0}, behind[3] = {0.0, 2.0, 0.0};
  api.reeds_shepp_path(space, from, behind, types, lengths, &total);
  EXPECT_DOUBLE_EQ(total, 2.0);
  double driven = 0.0;
  for (int i = 0; i < 5; ++i) {
    if (types[i] == 0 || lengths[i] == 0.0) continue;
    EXPECT_EQ(types[i], 2) << i;  // straight
    driven += lengths[i];
  }
  EXPECT_DOUBLE_EQ(driven, -2.0);
  // A quarter turn to the left, forwards: one left arc of pi/2 radii.
  const double origin[3] = {0.0, 0.0, 0.0}, quarter[3] = {0.5, 0.5, kPi / 2};
  api.reeds_shepp_path(space, origin, quarter, types, lengths, &total);
  EXPECT_NEAR(total, kPi / 2, 1e-12);
  api.reeds_shepp_delete(space);
}

// What OmplIsLoadedOnFirstUse checks, in a process of its own; returns the first broken
// expectation, or empty.
std::string firstUseProblem() {
  if (mapped("libompl") || mapped("libparksim_ompl_plugin")) return "OMPL is mapped at start-up";
  const ReedsSheppSteering steering(RobotDef{});
  if (!mapped("libparksim_ompl_plugin") || !mapped("libompl")) return "the plugin is not loaded";
  const double d = steering.distance({0.0, 0.0, 0.0}, {0.3, 0.0, 0.0});
  if (std::abs(d - 0.3) > 1e-12) return "a 0.3 m straight measured " + std::to_string(d);
  return "";
}

// OMPL (with Boost and ODE) is loaded with the plugin, when Reeds-Shepp curves are first
// wanted, not at start-up: a death test runs this in a fresh process.
TEST(OmplPluginDeathTest, OmplIsLoadedOnFirstUse) {
  testing::expectNoProblemInAFreshProcess(firstUseProblem);
}

}  // namespace
}  // namespace parksim
