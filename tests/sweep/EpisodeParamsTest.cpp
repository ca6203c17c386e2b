#include "parksim/sweep/spec/EpisodeParams.h"

#include <cmath>
#include <set>

#include <gtest/gtest.h>

#include "parksim/core/io/Error.h"
#include "parksim/pipeline/EpisodeSettings.h"
#include "parksim/results/tables/EpisodeRecord.h"
#include "parksim/scenario/world/World.h"
#include "parksim/sweep/spec/EpisodeExpansion.h"
#include "parksim/sweep/spec/EpisodeSetup.h"
#include "parksim/sweep/spec/SweepSpecReader.h"
#include "tests/support/TestPaths.h"
#include "tests/sweep/SweepTestSupport.h"

namespace parksim {
namespace {

TEST(EpisodeParams, CanonicalTextSpellsEveryParameterWithTheFormat) {
  EpisodeParams p;
  p.world = "head_in";
  p.seed = 7;
  const std::string defaults =
      "ids=3;world=head_in;planner=time-a-star;steering=balkcom-mason;smooth=1;seed=7;"
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
            "ids=3;world=head_in;planner=time-a-star;steering=balkcom-mason;smooth=0;seed=7;"
            "max_iterations=5000;tracking=closed;timing=time-optimal;realism=world;noise_seed=1;"
            "start_offset=0.01,0.0,-2.5;goal_offset=0.0,0.0,0.0");
}

// Keys after the core are spelled only when set, so that one more such key (a controller's
// name) leaves the ids of every episode that does not use it as they are.
TEST(EpisodeParams, ExtensionKeysAreSpelledOnlyWhenSet) {
  EpisodeParams p;
  p.world = "head_in";
  const std::string core = canonicalString(p);
  EXPECT_EQ(core.find("sample"), std::string::npos);
  p.sample = 4;
  p.world_set["robot.max_wheel_speed_radps"] = "6";
  p.world_set["goal.pose"] = "[1.5,0.04,-90]";
  p.planner_params["step_m"] = "0.05";
  p.controller_params["k_x"] = "true";
  EXPECT_EQ(canonicalString(p), core +
                                    ";sample=4;set.goal.pose=[1.5,0.04,-90];"
                                    "set.robot.max_wheel_speed_radps=6;planner.step_m=0.05;"
                                    "controller.k_x=true");
  EXPECT_EQ(setColumnsOf(p), (std::vector<std::string>{"goal.pose", "robot.max_wheel_speed_radps",
                                                       "planner.step_m", "controller.k_x"}));
  nlohmann::ordered_json row;
  appendParamColumns(p, row);
  EXPECT_EQ(row["sample"], 4);
  EXPECT_EQ(row["robot.max_wheel_speed_radps"], 6);
  EXPECT_EQ(row["goal.pose"], nlohmann::ordered_json::parse("[1.5,0.04,-90]"));
  EXPECT_EQ(row["planner.step_m"], 0.05);
  EXPECT_EQ(row["controller.k_x"], true);
}

// The row's fixed parameter columns are the record's parameter fields, in its order: the
// schema lists them, appendParamColumns gives their values.
TEST(EpisodeParams, ParameterColumnsAreTheRecordsParameterFields) {
  EpisodeParams p;
  p.sample = 0;
  nlohmann::ordered_json row;
  row["episode_id"] = "x";
  appendParamColumns(p, row);
  std::vector<std::string> keys;
  for (const auto& [key, value] : row.items()) keys.push_back(key);
  std::vector<std::string> fields;
  for (const EpisodeField& f : episodeFields()) {
    if (f.group == FieldGroup::kIdentity || f.group == FieldGroup::kParameter) {
      fields.emplace_back(f.key);
    }
  }
  EXPECT_EQ(keys, fields);
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
  EXPECT_TRUE(differs([](EpisodeParams& p) { p.sample = 0; }));
  EXPECT_TRUE(differs([](EpisodeParams& p) { p.world_set["robot.mass_kg"] = "1"; }));
  EXPECT_TRUE(differs([](EpisodeParams& p) { p.planner_params["k"] = "1"; }));
  EXPECT_TRUE(differs([](EpisodeParams& p) { p.controller_params["k"] = "1"; }));
}

std::vector<std::string> idsOf(const std::string& axes) {
  const SweepSpec spec = parseSweepSpec(testing::studySpec(axes), "spec.yaml", "");
  const std::vector<SweepWorld> worlds = loadSweepWorlds(spec);
  std::vector<std::string> ids;
  for (const SweepEpisode& e : expandEpisodes(spec, worlds)) ids.push_back(e.id);
  return ids;
}

TEST(EpisodeExpansion, SetAxesReachAMapsFields) {
  // The ROS lab's map inflated two ways and its unknown cells read two ways: four episodes, each
  // with its values in params.world_set and an id of its own.
  const std::string spec_text = "format: parksim-sweep/1\nname: t\nworlds: [" +
                                testing::sourceDir() +
                                "/worlds/ros_lab.yaml]\nset:\n  map[0].inflation: [0, 0.02]\n"
                                "  map[0].unknown: [occupied, free]\n";
  const SweepSpec spec = parseSweepSpec(spec_text, "spec.yaml", "");
  const std::vector<SweepWorld> worlds = loadSweepWorlds(spec);
  const std::vector<SweepEpisode> episodes = expandEpisodes(spec, worlds);
  ASSERT_EQ(episodes.size(), 4u);
  std::set<std::string> ids;
  std::shared_ptr<const World> plain, inflated;
  for (const SweepEpisode& e : episodes) {
    ids.insert(e.id);
    const ParamMap& set = e.params.world_set;
    if (set.at("map[0].unknown") != "occupied") continue;
    (set.at("map[0].inflation") == "0" ? plain : inflated) = episodeWorld(e.params, e.world);
  }
  EXPECT_EQ(ids.size(), 4u);
  ASSERT_TRUE(plain && inflated);
  // Inflation grows the map's obstacle (a pose 1 cm above the bottom wall is then in it); the
  // world hash follows the values.
  EXPECT_NE(plain->content_hash, inflated->content_hash);
  const OrientedBox near_wall = footprintAt(plain->scenario.robot, {2.5, -0.1475, 0.0});
  EXPECT_GT(separation(near_wall, plain->scenario.obstacles[0]), 0.0);
  EXPECT_LT(separation(near_wall, inflated->scenario.obstacles[0]), 0.0);
  // A value the world refuses is named by its axis and the spec's line, before anything runs.
  try {
    const SweepSpec bad =
        parseSweepSpec("format: parksim-sweep/1\nname: t\nworlds: [" + testing::sourceDir() +
                           "/worlds/ros_lab.yaml]\nset:\n  map[0].inflation: [0, -1]\n",
                       "spec.yaml", "");
    (void)expandEpisodes(bad, loadSweepWorlds(bad));
    FAIL() << "accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("map[0].inflation"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("spec.yaml:5"), std::string::npos) << e.what();
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
  const std::string path = parksim::testing::sourceDir() + "/worlds/head_in.yaml";
  const SweepWorld file = std::make_shared<const SweepWorldFile>(path, readWorldFile(path));
  const std::shared_ptr<const World> sweep_world = episodeWorld(EpisodeParams{}, file);
  EXPECT_EQ(sweep_world.get(), &file->world);  // no set: values: the file's world, shared
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
