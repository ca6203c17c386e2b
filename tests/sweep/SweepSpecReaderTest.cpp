#include "parksim/sweep/SweepSpecReader.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "parksim/core/Error.h"
#include "tests/support/TestPaths.h"
#include "tests/sweep/SweepTestSupport.h"

namespace parksim {
namespace {

using ::testing::HasSubstr;
using testing::studySpec;

std::string errorOf(const std::string& text) {
  try {
    (void)parseSweepSpec(text, "spec.yaml", "");
  } catch (const Error& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(SweepSpecReader, ReadsEveryAxis) {
  const SweepSpec s = parseSweepSpec(
      studySpec("planners: [rrt, rrt-star]\nsteering: rotate-translate-rotate\n"
                "smoothing: [false, true]\nseeds: {from: 3, to: 7}\nmax_iterations: [500]\n"
                "tracking: [open, closed]\ntiming: [study]\nrealism: [ideal, lab]\n"
                "noise_seeds: {from: 1, to: 3}\n"
                "start_offsets: [[0, 0, 0], [0.01, -0.02, 5]]\n"
                "record: {executed_csv: failures, executed_rate_hz: 30, film_failures: true,\n"
                "         film: {fps: 10, size: 320x240, view: both, video: false}}\n"
                "tolerance: {max_pos_err_m: 0.01, max_contacts: 1}\n"),
      "spec.yaml", "");
  EXPECT_EQ(s.world_paths.size(), 1u);
  EXPECT_EQ(s.planners, (std::vector<std::string>{"rrt", "rrt-star"}));
  EXPECT_EQ(s.steerings, (std::vector<std::string>{"rotate-translate-rotate"}));
  EXPECT_EQ(s.smoothing, (std::vector<bool>{false, true}));
  EXPECT_EQ(s.seeds, (std::vector<std::uint64_t>{3, 4, 5, 6, 7}));
  EXPECT_EQ(s.max_iterations, (std::vector<int>{500}));
  EXPECT_EQ(s.tracking, (std::vector<std::string>{"open", "closed"}));
  EXPECT_EQ(s.realism, (std::vector<std::string>{"ideal", "lab"}));
  EXPECT_EQ(s.noise_seeds, (std::vector<std::uint64_t>{1, 2, 3}));
  ASSERT_EQ(s.start_offsets.size(), 2u);
  EXPECT_EQ(s.start_offsets[1], (PoseOffset{0.01, -0.02, 5.0}));
  EXPECT_EQ(s.goal_offsets.size(), 1u);
  EXPECT_EQ(s.record.executed_csv, ExecutedCsvPolicy::kFailures);
  EXPECT_EQ(s.record.executed_rate_hz, 30.0);
  EXPECT_TRUE(s.record.film_failures);
  EXPECT_EQ(s.record.film_width_px, 320);
  EXPECT_EQ(s.record.film_view, "both");
  EXPECT_EQ(s.tolerance.max_pos_err_m, 0.01);
  EXPECT_EQ(s.tolerance.max_contacts, 1);
  EXPECT_FALSE(s.tolerance.goal_pos_err_m.has_value());
}

TEST(SweepSpecReader, ErrorsNameFileLineAndField) {
  EXPECT_EQ(errorOf(studySpec("planners: [rrt, rrt*]\n")),
            "spec.yaml:4: planners[1]: unknown planner 'rrt*' (this build has: rrt, "
            "rrt-goal-connect, rrt-star, rrt-connect, hybrid-a-star)");
  EXPECT_EQ(errorOf(studySpec("seeds: [1, 2,\n  1]\n")), "spec.yaml:5: seeds[2]: repeats seeds[0]");
  EXPECT_EQ(errorOf(studySpec("seeds: {from: 5, to: 2}\n")),
            "spec.yaml:4: seeds.to: must be at least from (5)");
  EXPECT_THAT(errorOf(studySpec("realism: [ideal, perfect]\n")),
              HasSubstr("spec.yaml:4: realism[1]: unknown realism 'perfect' (this build has: "
                        "world, ideal"));
  EXPECT_THAT(errorOf(studySpec("realism: ideal\nnoise_seeds: {from: 1, to: 3}\n")),
              HasSubstr("spec.yaml:5: noise_seeds: the ideal realism has no random draws"));
  EXPECT_THAT(errorOf(studySpec("timing: optimal\n")),
              HasSubstr("spec.yaml:4: timing: unknown timing 'optimal' (this build has: "
                        "time-optimal, study)"));
  EXPECT_THAT(
      errorOf(studySpec("planner: rrt\n")),
      HasSubstr("spec.yaml:4: planner: unknown field; expected one of: format, name, worlds"));
  EXPECT_THAT(errorOf(studySpec("start_offsets: [[0, 0]]\n")),
              HasSubstr("spec.yaml:4: start_offsets[0]: must be a list [dx_m, dy_m, dyaw_deg]"));
  EXPECT_THAT(errorOf(studySpec("record: {executed_csv: some}\n")),
              HasSubstr("spec.yaml:4: record.executed_csv: must be none, failures or all"));
  EXPECT_THAT(errorOf("format: parksim-sweep/2\nname: x\nworlds: a.yaml\n"),
              HasSubstr("spec.yaml:1: format: expected \"parksim-sweep/1\""));
  EXPECT_THAT(errorOf("format: parksim-sweep/1\nname: x\nworlds: [nope.yaml]\n"),
              HasSubstr("spec.yaml:3: worlds[0]: no such file"));
  EXPECT_THAT(errorOf("format: parksim-sweep/1\nname: x\nworlds: [\"nope*.yaml\"]\n"),
              HasSubstr("spec.yaml:3: worlds[0]: matches no file"));
  EXPECT_THAT(errorOf("format: parksim-sweep/1\nname: x\n"),
              HasSubstr("spec.yaml:1: worlds: missing required field"));
}

TEST(SweepSpecReader, WorldsResolveAgainstTheSpecFolderAndGlobsExpandSorted) {
  const SweepSpec s = loadSweepSpec(parksim::testing::sourceDir() + "/worlds/sweeps/study.yaml");
  ASSERT_EQ(s.world_files.size(), 2u);
  EXPECT_EQ(s.world_files[0], "../head_in.yaml");
  EXPECT_EQ(s.world_files[1], "../parallel.yaml");
  const SweepSpec g = parseSweepSpec("format: parksim-sweep/1\nname: g\nworlds: \"../*.yaml\"\n",
                                     "g.yaml", parksim::testing::sourceDir() + "/worlds/sweeps");
  ASSERT_GE(g.world_files.size(), 2u);
  EXPECT_TRUE(std::is_sorted(g.world_files.begin(), g.world_files.end()));
  EXPECT_NE(std::find(g.world_files.begin(), g.world_files.end(), "../head_in.yaml"),
            g.world_files.end());
}

}  // namespace
}  // namespace parksim
