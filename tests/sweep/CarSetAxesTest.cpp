// A sweep over a car's steering limit (issue 38: `set: robot.max_steer_deg: [...]`): each
// episode's car has the value it was given, its default plan stays within that value's limits by
// the test-side checker, a wider lock turns tighter, and a lock no car has is refused at its line
// of the spec before anything runs.

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "parksim/collision/BulletCollisionWorld.h"
#include "parksim/core/io/Error.h"
#include "parksim/planner/base/PlanScenario.h"
#include "parksim/sweep/spec/EpisodeExpansion.h"
#include "parksim/sweep/spec/EpisodeSetup.h"
#include "parksim/sweep/spec/SweepSpecReader.h"
#include "tests/support/CarPlanChecker.h"
#include "tests/support/TestPaths.h"

namespace parksim {
namespace {

constexpr double kPi = 3.14159265358979323846;

std::string carSpec(const std::string& values) {
  return "format: parksim-sweep/1\nname: steer\nworlds: [" + testing::sourceDir() +
         "/worlds/car_bay_forward.yaml]\nseeds: [1]\nset:\n  robot.max_steer_deg: " + values + "\n";
}

std::string refusalOf(const std::string& values) {
  try {
    const SweepSpec spec = parseSweepSpec(carSpec(values), "steer.yaml", "");
    (void)expandEpisodes(spec, loadSweepWorlds(spec));
  } catch (const Error& e) {
    return e.what();
  }
  return "accepted";
}

// The largest |tan(steer)| / axle_distance the plan turns at, from its rows' own motion: yaw rate
// over speed (the checker's bicycle), so that the test does not read the planner's curvature.
double tightestCurvature(const Trajectory& plan, const RobotDef& car) {
  double k = 0.0;
  for (const TrajectoryPoint& p : plan.points) {
    const testing::car_check::Motion m = testing::car_check::motionOf(p, car);
    if (std::abs(m.v) > 1e-6) k = std::max(k, std::abs(m.omega / m.v));
  }
  return k;
}

TEST(CarSetAxes, EachEpisodesCarSteersWithinItsOwnLock) {
  const SweepSpec spec = parseSweepSpec(carSpec("[20, 36.7]"), "steer.yaml", "");
  const std::vector<SweepEpisode> episodes = expandEpisodes(spec, loadSweepWorlds(spec));
  ASSERT_EQ(episodes.size(), 2u);
  std::map<double, double> tightest;  // lock (deg) -> the plan's tightest curvature (1/m)
  for (const SweepEpisode& e : episodes) {
    const double deg = std::stod(e.params.world_set.at("robot.max_steer_deg"));
    const std::shared_ptr<const World> world = episodeWorld(e.params, e.world);
    const Scenario& s = world->scenario;
    ASSERT_TRUE(s.robot.isCar());
    EXPECT_NEAR(s.robot.max_steer_rad, deg * kPi / 180.0, 1e-12);
    const BulletCollisionWorld checker(s);
    PlanSetup setup;
    setup.search.record_tree = false;
    const PlanResult r = planScenario(s, checker, setup);
    ASSERT_TRUE(r.solved()) << deg << " deg: " << r.message;
    std::string problems;
    for (const std::string& p : testing::carPlanViolations(s, r.trajectory)) problems += p + "\n";
    EXPECT_TRUE(problems.empty()) << deg << " deg:\n" << problems;
    const double limit = std::tan(deg * kPi / 180.0) / s.robot.axle_distance_m;
    tightest[deg] = tightestCurvature(r.trajectory, s.robot);
    EXPECT_LE(tightest[deg], limit * (1.0 + 1e-6)) << deg << " deg";
  }
  // The wider lock is used: the 36.7 deg car turns tighter than a 20 deg car can.
  EXPECT_GT(tightest.at(36.7), std::tan(20.0 * kPi / 180.0) / 2.8);
}

TEST(CarSetAxes, ALockNoCarHasIsRefusedAtItsLine) {
  // tan(80 deg) = 5.67: 2.8 m / 5.67 = 0.49 m, under half the 1.6 m track.
  const std::string e = refusalOf("[30, 80]");
  EXPECT_EQ(e.rfind("steer.yaml:6: set: robot.max_steer_deg=80: ", 0), 0u) << e;
  EXPECT_NE(e.find("smaller than half the track"), std::string::npos) << e;
  EXPECT_EQ(refusalOf("[30, -5]").rfind("steer.yaml:6: ", 0), 0u);
  EXPECT_EQ(refusalOf("[30, 40]"), "accepted");
}

}  // namespace
}  // namespace parksim
