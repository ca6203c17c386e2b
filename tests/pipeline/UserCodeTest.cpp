// A user's planner or controller that fails is a verdict, never an input error or a crash of
// the episode: planner_error, controller_error or plan_invalid, with one line saying what,
// when and where (pipeline/Verdict.h). The components come from tests/plugin/FaultyPlugin.cpp.

#include <memory>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "parksim/core/io/Error.h"
#include "parksim/pipeline/EpisodePipeline.h"
#include "parksim/pipeline/EpisodeSettings.h"
#include "parksim/results/episode/TrajectoryFile.h"
#include "parksim/scenario/world/World.h"
#include "parksim/usercode/PluginLoader.h"
#include "tests/support/TestPaths.h"

namespace parksim {
// Named, not anonymous: its program is compiled as one unity batch, where another file's
// helpers of the same names would meet these.
namespace user_code_test {

using ::testing::HasSubstr;
using ::testing::MatchesRegex;

std::shared_ptr<const Components> plugins() {
  static const std::shared_ptr<const Components> c =
      loadComponents({testing::binaryDir() + "/tests/plugin/libparksim_faulty_plugin.so",
                      testing::binaryDir() + "/examples/plugins/libparksim_example_plugins.so"});
  return c;
}

EpisodeRequest headIn(const std::string& realism = "ideal") {
  EpisodeRequest r;
  r.world = std::make_shared<const World>(loadWorld(testing::sourceDir() + "/worlds/head_in.yaml"));
  r.components = plugins();
  r.realism = realism;
  return r;
}

TEST(UserCode, APlannerThatThrowsIsAPlannerError) {
  EpisodeRequest r = headIn();
  r.plan.planner = "throwing-planner";
  const EpisodeOutcome out = runEpisodePipeline(r);
  EXPECT_EQ(out.verdict.status, EpisodeStatus::kPlannerError);
  EXPECT_EQ(out.verdict.reason, "planner throwing-planner threw: no idea how to park");
  EXPECT_FALSE(out.driven());
}

TEST(UserCode, APlanThatIsNotANumberIsAPlannerError) {
  EpisodeRequest r = headIn();
  r.plan.planner = "nan-planner";
  const EpisodeOutcome out = runEpisodePipeline(r);
  EXPECT_EQ(out.verdict.status, EpisodeStatus::kPlannerError);
  EXPECT_THAT(out.verdict.reason,
              MatchesRegex("planner nan-planner returned an unusable plan: row [0-9]+ holds a "
                           "value that is not finite"));
}

TEST(UserCode, APlanThroughObstaclesIsInvalidAndNamesWhereAndWhat) {
  EpisodeRequest r = headIn();
  r.plan.planner = "through-walls";
  const EpisodeOutcome out = runEpisodePipeline(r);
  EXPECT_EQ(out.verdict.status, EpisodeStatus::kPlanInvalid);
  EXPECT_THAT(out.verdict.reason,
              MatchesRegex("at t = [0-9.]+ s \\(x [0-9.]+ m, y [0-9.]+ m, -?[0-9.]+ deg\\) the "
                           "footprint overlaps (wall|robot|island)_[0-9]+.*"));
  EXPECT_FALSE(out.driven());
}

TEST(UserCode, APlanOverTheRobotsLimitsIsInvalidAndNamesTheLimit) {
  EpisodeRequest r = headIn();
  r.plan.planner = "too-fast-planner";
  const EpisodeOutcome out = runEpisodePipeline(r);
  EXPECT_EQ(out.verdict.status, EpisodeStatus::kPlanInvalid);
  EXPECT_THAT(out.verdict.reason, HasSubstr("robot.max_wheel_"));
}

// The commands of the first second are the plan's; then the fault, at t = 1 s.
TEST(UserCode, AControllerThatFailsEndsTheEpisodeWithAControllerError) {
  struct Case {
    const char* controller;
    const char* realism;
    const char* reason;
  };
  for (const Case& c :
       {Case{"throwing-controller", "ideal",
             "controller throwing-controller threw in command at t = 1.000 s: lost track"},
        Case{"throwing-controller", "lab",
             "controller throwing-controller threw in command at t = 1.000 s: lost track"},
        Case{"nan-controller", "ideal",
             "controller nan-controller returned (nan, 0) rad/s at t = 1.000 s: not a number"},
        Case{"too-fast-controller", "lab",
             "controller too-fast-controller returned (20, 20) rad/s at t = 1.000 s: beyond "
             "robot.max_wheel_speed_radps 10"},
        Case{"throwing-reset", "ideal",
             "controller throwing-reset threw in reset at t = 0.000 s: cannot read the plan"}}) {
    SCOPED_TRACE(std::string(c.controller) + " " + c.realism);
    EpisodeRequest r = headIn(c.realism);
    r.controller = c.controller;
    const EpisodeOutcome out = runEpisodePipeline(r);
    EXPECT_EQ(out.verdict.status, EpisodeStatus::kControllerError);
    EXPECT_EQ(out.verdict.reason, c.reason);
    ASSERT_TRUE(out.driven());
    // The record up to the failure is kept, and ends there.
    const double end = std::string(c.controller) == "throwing-reset" ? 0.0 : 1.0;
    EXPECT_NEAR(out.episode.metrics.sim_time_s, end, 0.005);
    EXPECT_NEAR(out.episode.rows.back().t_s, end, 0.005);
    EXPECT_EQ(out.episode.metrics.controller, c.controller);
  }
}

// A plugin's copy of the tracking controller drives exactly as the built-in one: going through
// the plugin API adds checks, not differences.
TEST(UserCode, ThePluginPathChangesNoCommand) {
  for (const char* realism : {"ideal", "lab"}) {
    EpisodeRequest built_in = headIn(realism);
    EpisodeRequest plugin = headIn(realism);
    plugin.controller = "tracking-copy";
    const EpisodeOutcome a = runEpisodePipeline(built_in);
    const EpisodeOutcome b = runEpisodePipeline(plugin);
    ASSERT_TRUE(a.verdict.met()) << a.verdict.reason;
    EXPECT_EQ(a.verdict, b.verdict);
    ASSERT_EQ(a.episode.rows.size(), b.episode.rows.size());
    for (std::size_t k = 0; k < a.episode.rows.size(); ++k) {
      ASSERT_EQ(a.episode.rows[k].pose, b.episode.rows[k].pose) << realism << " row " << k;
    }
  }
}

TEST(UserCode, TheExamplePluginParksLikeABuiltIn) {
  EpisodeRequest r = headIn();
  r.plan.planner = "example";
  r.controller = "pure-pursuit";
  const EpisodeOutcome out = runEpisodePipeline(r);
  EXPECT_TRUE(out.verdict.met()) << out.verdict.reason;
  EXPECT_EQ(out.plan_summary["planner"], "example");
  EXPECT_EQ(out.episode.metrics.controller, "pure-pursuit");
}

TEST(UserCode, UnknownNamesAndParametersAreInputErrors) {
  EpisodeRequest r = headIn();
  r.controller = "trackin";
  EXPECT_THROW(checkEpisodeRequest(r), Error);
  r = headIn();
  r.controller_params = {{"bandwith_radps", "3"}};
  EXPECT_THROW(checkEpisodeRequest(r), Error);
  r = headIn();
  r.plan.planner = "example";
  r.plan.planner_params = {{"cell_m", "x"}};
  EXPECT_THROW(checkEpisodeRequest(r), Error);
}

// A plan file is checked as a user planner's plan is: over the world's own limit here.
TEST(UserCode, AGivenPlanOverTheSpeedLimitIsInvalid) {
  EpisodeRequest planned = headIn();
  const EpisodeOutcome p = runEpisodePipeline(planned);
  ASSERT_TRUE(p.verdict.met());
  EpisodeRequest r = headIn();
  World slow = *r.world;
  slow.scenario.robot.max_wheel_speed_radps = 5.0;
  r.world = std::make_shared<const World>(slow);
  r.given_plan = p.trajectory;
  r.given_plan_source = "head_in plan";
  const EpisodeOutcome out = runEpisodePipeline(r);
  EXPECT_EQ(out.verdict.status, EpisodeStatus::kPlanInvalid);
  EXPECT_THAT(out.verdict.reason, HasSubstr("exceed robot.max_wheel_speed_radps 5"));
  EXPECT_FALSE(out.driven());
}

}  // namespace user_code_test
}  // namespace parksim
