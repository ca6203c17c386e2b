#include "parksim/sweep/EpisodeParams.h"

#include <cmath>
#include <set>

#include <gtest/gtest.h>

#include "parksim/core/Error.h"
#include "parksim/pipeline/EpisodeSettings.h"
#include "parksim/scenario/World.h"
#include "parksim/sweep/EpisodeExpansion.h"
#include "parksim/sweep/EpisodeSetup.h"
#include "parksim/sweep/SweepSpecReader.h"
#include "tests/support/TestPaths.h"
#include "tests/sweep/SweepTestSupport.h"

namespace parksim {
namespace {

TEST(EpisodeParams, CanonicalTextSpellsEveryParameterWithTheFormat) {
  EpisodeParams p;
  p.world = "head_in";
  p.seed = 7;
  const std::string defaults =
      "ids=2;world=head_in;planner=time-a-star;steering=balkcom-mason;smooth=1;seed=7;"
      "max_iterations=auto;tracking=closed;timing=time-optimal;realism=world;noise_seed=1;"
      "start_offset=0.0,0.0,0.0;goal_offset=0.0,0.0,0.0";
  EXPECT_EQ(canonicalString(p), defaults);
  EXPECT_EQ(episodeId(p), episodeId(p));
  EXPECT_EQ(episodeId(p).size(), 16u);
  p.world_file = "elsewhere/head_in.yaml";  // provenance, not identity
  EXPECT_EQ(canonicalString(p), defaults);
  p.smooth = false;
  p.max_iterations = 5000;
  p.start_offset = {0.01, 0.0, -2.5};
  EXPECT_EQ(canonicalString(p),
            "ids=2;world=head_in;planner=time-a-star;steering=balkcom-mason;smooth=0;seed=7;"
            "max_iterations=5000;tracking=closed;timing=time-optimal;realism=world;noise_seed=1;"
            "start_offset=0.01,0.0,-2.5;goal_offset=0.0,0.0,0.0");
}

TEST(EpisodeParams, DefaultsAreTheLibrarys) {
  const EpisodeParams p;
  const PlanSetup plan;
  const EpisodeRequest request;
  EXPECT_EQ(p.planner, plan.planner);
  EXPECT_EQ(p.steering, toString(plan.steering_kind));
  EXPECT_EQ(p.smooth, plan.search.smooth);
  EXPECT_EQ(p.seed, plan.search.seed);
  EXPECT_EQ(p.max_iterations, kAutoIterations);
  EXPECT_EQ(p.timing, toString(plan.timing));
  EXPECT_EQ(p.tracking, toString(kDefaultTracking));
  EXPECT_EQ(p.realism, request.realism);
  EXPECT_EQ(p.noise_seed, request.noise_seed);
}

TEST(EpisodeParams, EveryParameterChangesTheId) {
  const EpisodeParams base;
  std::set<std::string> ids = {episodeId(base)};
  auto differs = [&](auto change) {
    EpisodeParams p = base;
    change(p);
    return ids.insert(episodeId(p)).second;
  };
  EXPECT_TRUE(differs([](EpisodeParams& p) { p.world = "parallel"; }));
  EXPECT_TRUE(differs([](EpisodeParams& p) { p.planner = "rrt"; }));
  EXPECT_TRUE(differs([](EpisodeParams& p) { p.steering = "rotate-translate-rotate"; }));
  EXPECT_TRUE(differs([](EpisodeParams& p) { p.smooth = !p.smooth; }));
  EXPECT_TRUE(differs([](EpisodeParams& p) { p.seed = 2; }));
  EXPECT_TRUE(differs([](EpisodeParams& p) { p.max_iterations = 10; }));
  EXPECT_TRUE(differs([](EpisodeParams& p) { p.tracking = "open"; }));
  EXPECT_TRUE(differs([](EpisodeParams& p) { p.timing = "other"; }));
  EXPECT_TRUE(differs([](EpisodeParams& p) { p.realism = "lab"; }));
  EXPECT_TRUE(differs([](EpisodeParams& p) { p.noise_seed = 3; }));
  EXPECT_TRUE(differs([](EpisodeParams& p) { p.start_offset.dx_m = 0.001; }));
  EXPECT_TRUE(differs([](EpisodeParams& p) { p.goal_offset.dyaw_deg = 1.0; }));
}

std::vector<std::string> idsOf(const std::string& axes) {
  const SweepSpec spec = parseSweepSpec(testing::studySpec(axes), "spec.yaml", "");
  const std::vector<SweepWorld> worlds = loadSweepWorlds(spec);
  std::vector<std::string> ids;
  for (const SweepEpisode& e : expandEpisodes(spec, worlds)) ids.push_back(e.id);
  return ids;
}

TEST(EpisodeExpansion, SetAxesMakeNamedVariantsOfEveryWorld) {
  // The ROS lab's map inflated three ways: variants of the world, each with ids of its own.
  const std::string spec_text = "format: parksim-sweep/1\nname: t\nworlds: [" +
                                testing::sourceDir() +
                                "/worlds/ros_lab.yaml]\nset:\n  map[0].inflation: [0, 0.02]\n"
                                "  map[0].unknown: [occupied, free]\n";
  const SweepSpec spec = parseSweepSpec(spec_text, "spec.yaml", "");
  ASSERT_EQ(spec.world_paths.size(), 4u);
  const std::vector<SweepWorld> worlds = loadSweepWorlds(spec);
  EXPECT_EQ(worlds[0]->scenario.name, "ros_lab{map[0].inflation=0,map[0].unknown=occupied}");
  EXPECT_EQ(worlds[3]->scenario.name, "ros_lab{map[0].inflation=0.02,map[0].unknown=free}");
  // Inflation grows the map's obstacle (a pose 1 cm above the bottom wall is then in it); the
  // world hash follows the overrides.
  EXPECT_GT(worlds[2]->scenario.obstacles[0].compound->parts.size(), 0u);
  EXPECT_NE(worlds[0]->content_hash, worlds[2]->content_hash);
  const OrientedBox near_wall = footprintAt(worlds[0]->scenario.robot, {2.5, -0.1475, 0.0});
  EXPECT_GT(separation(near_wall, worlds[0]->scenario.obstacles[0]), 0.0);
  EXPECT_LT(separation(near_wall, worlds[2]->scenario.obstacles[0]), 0.0);
  std::vector<std::string> ids;
  for (const SweepEpisode& e : expandEpisodes(spec, worlds)) ids.push_back(e.id);
  EXPECT_EQ(std::set<std::string>(ids.begin(), ids.end()).size(), 4u);
  // A value the world refuses is named by its axis.
  try {
    (void)loadSweepWorlds(
        parseSweepSpec("format: parksim-sweep/1\nname: t\nworlds: [" + testing::sourceDir() +
                           "/worlds/ros_lab.yaml]\nset:\n  map[0].inflation: [0, -1]\n",
                       "spec.yaml", ""));
    FAIL() << "accepted";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.what()),
              "spec.yaml:5: set map[0].inflation=-1: map[0].inflation: "
              "must be in [0, 100] m, got -1");
  }
}

TEST(EpisodeExpansion, IdsDependOnParametersNotOnTheirPositionInTheSpec) {
  const std::vector<std::string> a = idsOf("planners: [rrt, rrt-connect]\nseeds: [1, 2, 3]\n");
  const std::vector<std::string> b = idsOf("planners: [rrt-connect, rrt]\nseeds: [3, 1, 2]\n");
  EXPECT_EQ(a.size(), 6u);
  EXPECT_EQ(a, b);  // canonical order: ascending id
  EXPECT_TRUE(std::is_sorted(a.begin(), a.end()));
  // A larger sweep holds the same episodes under the same ids.
  const std::vector<std::string> c =
      idsOf("planners: [rrt, rrt-connect, rrt-star]\nseeds: {from: 1, to: 4}\n");
  for (const std::string& id : a) {
    EXPECT_NE(std::find(c.begin(), c.end(), id), c.end()) << id;
  }
}

TEST(EpisodeSetup, AppliesOffsetsAndRejectsOnesThatLeaveTheLot) {
  const SweepWorld sweep_world = std::make_shared<const World>(
      loadWorld(parksim::testing::sourceDir() + "/worlds/head_in.yaml"));
  const Scenario& world = sweep_world->scenario;
  EpisodeParams p;
  p.world = world.name;
  p.start_offset = {0.01, -0.02, 0.0};
  p.goal_offset = {0.0, 0.0, 90.0};
  p.tracking = "open";
  p.seed = 9;
  p.realism = "lab";
  p.noise_seed = 4;
  p.timing = "study";
  ToleranceOverrides overrides;
  overrides.goal_pos_err_m = 0.01;
  const EpisodeRequest r = episodeRequest(p, sweep_world, overrides);
  const Scenario& moved = r.world->scenario;
  EXPECT_NE(r.world, sweep_world);  // a copy with the start and goal moved
  EXPECT_DOUBLE_EQ(moved.start.x, world.start.x + 0.01);
  EXPECT_DOUBLE_EQ(moved.start.y, world.start.y - 0.02);
  EXPECT_NEAR(std::remainder(moved.goal.pose.theta - world.goal.pose.theta - kPi / 2, 2 * kPi), 0.0,
              1e-12);
  const EpisodeSettings s = resolveSettings(r);
  EXPECT_EQ(s.plan.search.seed, 9u);
  EXPECT_EQ(s.execution.tracking, TrackingMode::kOpen);
  EXPECT_EQ(s.execution.realism.name, "lab");
  EXPECT_EQ(s.execution.noise_seed, 4u);
  EXPECT_EQ(s.plan.timing, TimingKind::kStudy);
  EXPECT_EQ(s.plan.search.max_iterations,
            defaultIterationBudget(builtInPlanners().find(s.plan.planner).info, world));
  EXPECT_EQ(s.tolerance.goal_pos_err_m, 0.01);
  EXPECT_EQ(s.tolerance.max_pos_err_m, TrackingTolerance{}.max_pos_err_m);
  // "world" keeps the world's realism (none here: the ideal robot); no offset shares the world.
  p.realism = "world";
  p.start_offset = {};
  p.goal_offset = {};
  const EpisodeRequest plain = episodeRequest(p, sweep_world, {});
  EXPECT_EQ(plain.world, sweep_world);
  EXPECT_EQ(resolveSettings(plain).execution.realism.name, "ideal");
  p.start_offset = {5.0, 0.0, 0.0};
  EXPECT_THROW((void)episodeRequest(p, sweep_world, {}), Error);
}

}  // namespace
}  // namespace parksim
