// One plan check for every door into the library (issue 39): a user planner's plan through a
// wall is plan_invalid whether it is planned alone (planScenario, `parksim plan`, `render`,
// Python's plan()) or planned and driven (the pipeline, `run`, sweeps, Python's run()), and the
// files of such an episode say so and say whose code it was. The planners come from
// tests/plugin/FaultyPlugin.cpp.

#include <filesystem>
#include <fstream>
#include <memory>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "parksim/collision/BulletCollisionWorld.h"
#include "parksim/pipeline/EpisodePipeline.h"
#include "parksim/planner/base/PlanScenario.h"
#include "parksim/scenario/world/World.h"
#include "parksim/usercode/PluginLoader.h"
#include "tests/support/TestPaths.h"

namespace parksim {
// Named, not anonymous: its program is compiled as one unity batch, where another file's
// helpers of the same names would meet these.
namespace one_plan_check_test {

namespace fs = std::filesystem;
using ::testing::HasSubstr;
using ::testing::MatchesRegex;
using ::testing::StartsWith;

const std::string& faultyPath() {
  static const std::string path =
      testing::binaryDir() + "/tests/plugin/libparksim_faulty_plugin.so";
  return path;
}

std::shared_ptr<const Components> plugins() {
  static const std::shared_ptr<const Components> c = loadComponents({faultyPath()});
  return c;
}

std::shared_ptr<const World> headIn() {
  static const auto w =
      std::make_shared<const World>(loadWorld(testing::sourceDir() + "/worlds/head_in.yaml"));
  return w;
}

EpisodeRequest request(const std::string& planner, bool drive, const std::string& out = "") {
  EpisodeRequest r;
  r.world = headIn();
  r.components = plugins();
  r.plan.planner = planner;
  r.drive = drive;
  r.out_dir = out;
  return r;
}

nlohmann::json readJson(const fs::path& path) {
  std::ifstream in(path);
  return nlohmann::json::parse(in);
}

fs::path freshDir(const std::string& name) {
  const fs::path dir = testing::testOutputDir("one_plan_check") / name;
  fs::remove_all(dir);
  return dir;
}

// The reason the check gives for through-walls' plan.
const char* const kThroughAWall =
    "at t = [0-9.]+ s \\(x [0-9.]+ m, y [0-9.]+ m, -?[0-9.]+ deg\\) the footprint overlaps "
    "(wall|robot|island)_[0-9]+.*";

TEST(OnePlanCheck, TheLibrarysPlanCallChecksAUserPlannersPlan) {
  const Scenario& s = headIn()->scenario;
  const BulletCollisionWorld collision(s);
  PlanSetup setup;
  setup.planner = "through-walls";
  const PlanResult r = planScenario(s, collision, setup, {}, plugins()->planners);
  EXPECT_EQ(r.status, PlanStatus::kPlanInvalid);
  EXPECT_FALSE(r.solved());
  EXPECT_THAT(r.message, MatchesRegex(kThroughAWall));
  // Kept to be looked at: the plan that failed.
  EXPECT_FALSE(r.trajectory.empty());
  // parksim's own planners are not checked again: solved.
  EXPECT_TRUE(planScenario(s, collision, PlanSetup{}).solved());
}

TEST(OnePlanCheck, PlanningAloneGivesTheVerdictAndThePlansStatusAlike) {
  const EpisodeOutcome out = runEpisodePipeline(request("through-walls", false));
  EXPECT_EQ(out.verdict.status, EpisodeStatus::kPlanInvalid);
  ASSERT_TRUE(out.plan);
  EXPECT_EQ(out.plan->status, PlanStatus::kPlanInvalid);
  EXPECT_EQ(out.plan->message, out.verdict.reason);
  EXPECT_EQ(out.plan_summary["status"], "plan_invalid");
  EXPECT_EQ(out.plan_summary["solved"], false);
  // Shown on the episode's page, never driven.
  EXPECT_FALSE(out.trajectory.empty());
  EXPECT_FALSE(out.driven());
  EXPECT_TRUE(out.metrics.empty());
}

TEST(OnePlanCheck, APlanInvalidRunWritesItsVerdictAndWhoseCodeItWas) {
  const fs::path dir = freshDir("invalid");
  const EpisodeOutcome out = runEpisodePipeline(request("through-walls", true, dir.string()));
  ASSERT_EQ(out.verdict.status, EpisodeStatus::kPlanInvalid);
  const std::string origin =
      "plugin parksim-faults 0.1 (" + fs::absolute(faultyPath()).lexically_normal().string();
  const nlohmann::json plan = readJson(dir / "plan.json");
  EXPECT_EQ(plan["status"], "plan_invalid");
  EXPECT_EQ(plan["planner"], "through-walls");
  EXPECT_THAT(plan["planner_origin"].get<std::string>(), StartsWith(origin));
  const nlohmann::json metrics = readJson(dir / "metrics.json");
  EXPECT_EQ(metrics["status"], "plan_invalid");
  EXPECT_EQ(metrics["met_tolerance"], false);
  EXPECT_EQ(metrics["failure"], out.verdict.reason);
  EXPECT_EQ(metrics["plan_planner_origin"], plan["planner_origin"]);
  EXPECT_THAT(metrics["provenance.plugins"].get<std::string>(), StartsWith("parksim-faults 0.1 "));
  // Nothing was driven, so nothing was measured, and no plan that may be driven is written.
  EXPECT_FALSE(metrics.contains("max_pos_err_m"));
  EXPECT_FALSE(fs::exists(dir / "trajectory.csv"));
  EXPECT_FALSE(fs::exists(dir / "executed.csv"));
  EXPECT_EQ(out.files, (std::vector<std::string>{"plan.json", "report.html", "metrics.json"}));
}

TEST(OnePlanCheck, APlannerErrorWritesItsVerdictAndWhoseCodeItWas) {
  const fs::path dir = freshDir("error");
  const EpisodeOutcome out = runEpisodePipeline(request("throwing-planner", true, dir.string()));
  ASSERT_EQ(out.verdict.status, EpisodeStatus::kPlannerError);
  const nlohmann::json plan = readJson(dir / "plan.json");
  EXPECT_EQ(plan["status"], "planner_error");
  EXPECT_EQ(plan["solved"], false);
  EXPECT_EQ(plan["message"], "planner throwing-planner threw: no idea how to park");
  EXPECT_EQ(plan["planner"], "throwing-planner");
  EXPECT_THAT(plan["planner_origin"].get<std::string>(), HasSubstr("libparksim_faulty_plugin.so"));
  const nlohmann::json metrics = readJson(dir / "metrics.json");
  EXPECT_EQ(metrics["status"], "planner_error");
  EXPECT_EQ(metrics["failure"], plan["message"]);
}

// parksim's own plans carry no origin: their files are what they were.
TEST(OnePlanCheck, ParksimsOwnPlanHasNoOrigin) {
  const fs::path dir = freshDir("own");
  const EpisodeOutcome out = runEpisodePipeline(request("time-a-star", true, dir.string()));
  ASSERT_TRUE(out.verdict.met()) << out.verdict.reason;
  EXPECT_FALSE(readJson(dir / "plan.json").contains("planner_origin"));
}

}  // namespace one_plan_check_test
}  // namespace parksim
