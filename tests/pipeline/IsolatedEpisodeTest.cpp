// An episode in a watched worker (pipeline/IsolatedEpisode.h): the same outcome as in the
// caller's process, to the bit, and user code that crashes or hangs is a verdict, not the
// caller's end. The faulty components come from tests/plugin/FaultyPlugin.cpp.

#include <memory>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "parksim/pipeline/EpisodePipeline.h"
#include "parksim/pipeline/IsolatedEpisode.h"
#include "parksim/results/episode/MetricsFile.h"
#include "parksim/scenario/world/World.h"
#include "parksim/usercode/PluginLoader.h"
#include "tests/support/TestPaths.h"

namespace parksim {
namespace {

using ::testing::HasSubstr;

std::shared_ptr<const Components> plugins() {
  static const std::shared_ptr<const Components> c =
      loadComponents({testing::binaryDir() + "/tests/plugin/libparksim_faulty_plugin.so"});
  return c;
}

EpisodeRequest headIn(const std::string& realism) {
  EpisodeRequest r;
  r.world = std::make_shared<const World>(loadWorld(testing::sourceDir() + "/worlds/head_in.yaml"));
  r.components = plugins();
  r.realism = realism;
  return r;
}

// `j` without the wall-clock measurements, which differ between two runs of one episode.
nlohmann::json withoutClocks(nlohmann::json j) {
  for (const char* key : {"planning_time_s", "first_solution_s", "phase_times_s", "cost_history",
                          "wall_time_s", "real_time_factor"}) {
    j.erase(key);
  }
  return j;
}

void expectSameOutcome(const EpisodeOutcome& a, const EpisodeOutcome& b) {
  EXPECT_EQ(a.verdict, b.verdict);
  ASSERT_EQ(a.plan.has_value(), b.plan.has_value());
  if (a.plan) {
    EXPECT_EQ(a.plan->status, b.plan->status);
    EXPECT_EQ(a.plan->trajectory, b.plan->trajectory);
    EXPECT_EQ(a.plan->waypoints, b.plan->waypoints);
    EXPECT_EQ(a.plan->cost, b.plan->cost);
    EXPECT_EQ(a.plan->stats.iterations, b.plan->stats.iterations);
  }
  EXPECT_EQ(a.trajectory, b.trajectory);
  EXPECT_EQ(withoutClocks(a.plan_summary), withoutClocks(b.plan_summary));
  ASSERT_EQ(a.episode.rows.size(), b.episode.rows.size());
  for (std::size_t k = 0; k < a.episode.rows.size(); ++k) {
    ASSERT_EQ(a.episode.rows[k].pose, b.episode.rows[k].pose) << "row " << k;
    ASSERT_EQ(a.episode.rows[k].encoder_rad, b.episode.rows[k].encoder_rad) << "row " << k;
  }
  EXPECT_EQ(a.episode.pose_samples.size(), b.episode.pose_samples.size());
  // Every measurement metrics.json holds, wall time aside (two drives, two clocks).
  EXPECT_EQ(withoutClocks(metricsToJson(a.episode.metrics)),
            withoutClocks(metricsToJson(b.episode.metrics)));
  ASSERT_EQ(a.realisations.size(), b.realisations.size());
  for (std::size_t k = 0; k < a.realisations.size(); ++k) {
    EXPECT_EQ(a.realisations[k].noise_seed, b.realisations[k].noise_seed);
    EXPECT_EQ(a.realisations[k].verdict, b.realisations[k].verdict);
    EXPECT_EQ(a.realisations[k].metrics.max_pos_err_m, b.realisations[k].metrics.max_pos_err_m);
  }
  EXPECT_EQ(a.execution.realism.active(), b.execution.realism.active());
  EXPECT_EQ(a.files, b.files);
}

// The bytes carry every part the caller does not have: a lab episode with its contacts, slip,
// estimate and pose samples reads back equal, field by field.
TEST(IsolatedEpisode, TheOutcomeReadsBackExactly) {
  EpisodeRequest r = headIn("lab");
  r.realisations = 2;
  const EpisodeOutcome out = runEpisodePipeline(r);
  ASSERT_TRUE(out.driven());
  ASSERT_FALSE(out.episode.pose_samples.empty());
  const EpisodeOutcome back =
      decodeOutcome(encodeOutcome(out), out.world, out.plan_setup, out.execution, out.tolerance);
  expectSameOutcome(out, back);
  // Wall time too: the bytes are the same numbers.
  EXPECT_EQ(metricsToJson(out.episode.metrics), metricsToJson(back.episode.metrics));
  EXPECT_EQ(out.metrics, back.metrics);
  // Bytes cut short are an error, not a wrong outcome.
  const std::string bytes = encodeOutcome(out);
  EXPECT_THROW(decodeOutcome(std::string_view(bytes).substr(0, bytes.size() / 2), out.world,
                             out.plan_setup, out.execution, out.tolerance),
               Error);
}

TEST(IsolatedEpisode, InAWorkerAnEpisodeIsTheSameAsInTheCallersProcess) {
  for (const char* realism : {"ideal", "lab"}) {
    SCOPED_TRACE(realism);
    EpisodeRequest r = headIn(realism);
    r.controller = "tracking-copy";  // a plugin's: user code, watched
    expectSameOutcome(runEpisodePipeline(r), runEpisodeIsolated(r));
  }
}

TEST(IsolatedEpisode, UserCodeThatCrashesOrHangsIsTheVerdict) {
  struct Case {
    const char* planner;
    const char* controller;
    EpisodeStatus status;
    const char* reason;
  };
  for (const Case& c :
       {Case{"segfault-planner", "tracking", EpisodeStatus::kPlannerError,
             "planner segfault-planner crashed (SIGSEGV, Segmentation fault)"},
        Case{"hanging-planner", "tracking", EpisodeStatus::kPlannerError,
             "planner hanging-planner ran past its time limit of 0.5 s (its process was killed)"},
        Case{"time-a-star", "hanging-controller", EpisodeStatus::kControllerError,
             "controller hanging-controller gave no command within its time limit of 0.5 s (its "
             "process was killed)"}}) {
    SCOPED_TRACE(c.planner + std::string(" ") + c.controller);
    EpisodeRequest r = headIn("ideal");
    r.plan.planner = c.planner;
    r.controller = c.controller;
    r.limits = {.planner_s = 0.5, .controller_tick_s = 0.5};
    const EpisodeOutcome out = runEpisodeIsolated(r);
    EXPECT_EQ(out.verdict.status, c.status);
    EXPECT_EQ(out.verdict.reason, c.reason);
    EXPECT_FALSE(out.driven());
    // Recorded as the pipeline records a user's failure: the verdict in metrics.json's content,
    // and for a planner plan.json's, naming its code.
    EXPECT_EQ(out.metrics["status"], toString(c.status));
    if (c.status == EpisodeStatus::kPlannerError) {
      EXPECT_EQ(out.plan_summary["status"], "planner_error");
      EXPECT_THAT(out.plan_summary["planner_origin"].get<std::string>(),
                  HasSubstr("plugin parksim-faults"));
    }
  }
}

}  // namespace
}  // namespace parksim
