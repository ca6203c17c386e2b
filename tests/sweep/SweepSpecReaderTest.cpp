#include "parksim/sweep/spec/SweepSpecReader.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "parksim/core/io/Error.h"
#include "tests/support/TestPaths.h"
#include "tests/sweep/SweepTestSupport.h"

namespace parksim {
// Named, not anonymous: its program is compiled as one unity batch, where another file's
// helpers of the same names would meet these.
namespace sweep_spec_reader_test {

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
                "record: {executed_csv: failures, executed_rate_hz: 30, format: csv, "
                "film_failures: true,\n"
                "         film: {fps: 10, size: 320x240, view: both, video: false}}\n"
                "tolerance: {max_pos_err_m: 0.01, max_contacts: 1}\n"),
      "spec.yaml", "");
  EXPECT_EQ(s.world_paths.size(), 1u);
  ASSERT_EQ(s.planners.size(), 2u);
  EXPECT_EQ(s.planners[0].name, "rrt");
  EXPECT_EQ(s.planners[1].name, "rrt-star");
  EXPECT_TRUE(s.planners[1].params.empty());
  ASSERT_EQ(s.controllers.size(), 1u);
  EXPECT_EQ(s.controllers[0].name, "tracking");
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
  EXPECT_EQ(s.record.executed_csv, FilesPolicy::kFailures);
  EXPECT_EQ(s.record.executed_rate_hz, 30.0);
  EXPECT_EQ(s.record.format, RecordFormat::kCsv);
  EXPECT_EQ(parseSweepSpec(studySpec(""), "spec.yaml", "").record.format, RecordFormat::kNpz);
  EXPECT_TRUE(s.record.film_failures);
  EXPECT_EQ(s.record.film_width_px, 320);
  EXPECT_EQ(s.record.film_view, "both");
  EXPECT_EQ(s.tolerance.max_pos_err_m, 0.01);
  EXPECT_EQ(s.tolerance.max_contacts, 1);
  EXPECT_FALSE(s.tolerance.goal_pos_err_m.has_value());
}

TEST(SweepSpecReader, ErrorsNameFileLineAndField) {
  // Which names exist is known once the spec's plugins are loaded (EpisodeExpansion: "unknown
  // planner 'nope' (this build has: ...)", tests/sweep/SweepCliTest.cpp); the reader refuses
  // what cannot be a name at all.
  EXPECT_EQ(errorOf(studySpec("planners: [rrt, rrt*]\n")),
            "spec.yaml:4: planners[1]: 'rrt*' is not a planner's name (1 to 64 letters, "
            "digits, '-', '_' or '.')");
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
  EXPECT_THAT(errorOf(studySpec("record: {format: parquet}\n")),
              HasSubstr("spec.yaml:4: record.format: must be npz or csv, got 'parquet'"));
  EXPECT_THAT(errorOf("format: parksim-sweep/2\nname: x\nworlds: a.yaml\n"),
              HasSubstr("spec.yaml:1: format: expected \"parksim-sweep/1\""));
  EXPECT_THAT(errorOf("format: parksim-sweep/1\nname: x\nworlds: [nope.yaml]\n"),
              HasSubstr("spec.yaml:3: worlds[0]: no such file"));
  EXPECT_THAT(errorOf("format: parksim-sweep/1\nname: x\nworlds: [\"nope*.yaml\"]\n"),
              HasSubstr("spec.yaml:3: worlds[0]: matches no file"));
  EXPECT_THAT(errorOf("format: parksim-sweep/1\nname: x\n"),
              HasSubstr("spec.yaml:1: worlds: missing required field"));
}

// The spec reader read files whole (/dev/zero until memory ran out) and parsed with
// YAML::LoadAll, which yaml-cpp 0.7 never ends on a stray ',' (1 GB/s): both found by the
// hostile pass. Specs now get the world reader's guards.
TEST(SweepSpecReader, MalformedYamlAndDevicesEndInOneLine) {
  EXPECT_EQ(errorOf(","),
            "spec.yaml:1: (syntax): unexpected ',' (outside any [ ] or { } list or map)");
  EXPECT_EQ(errorOf("format: parksim-sweep/1\nname: x\n---\nname: y\n"),
            "spec.yaml:4: (document): a sweep spec holds one YAML document, found 2");
  // The name was echoed raw: a spec turned the terminal red (hostile pass).
  EXPECT_EQ(errorOf("format: parksim-sweep/1\nname: \"\\e[31mred\"\nworlds: [a.yaml]\n"),
            "spec.yaml:2: name: must be UTF-8 text without control characters, got "
            "\"\\x1b[31mred\"");
  EXPECT_EQ(errorOf(""),
            "spec.yaml:1: (document): empty; a sweep spec is a map that starts with format: "
            "parksim-sweep/1");
  try {
    (void)loadSweepSpec("/dev/zero");
    ADD_FAILURE() << "/dev/zero accepted";
  } catch (const Error& e) {
    EXPECT_THAT(std::string(e.what()), HasSubstr("/dev/zero: is not a regular file"));
  }
}

// Seeds went through a double: 9007199254740993 ran as ...992 without a word, and a range up
// to the largest seed never ended (std::bad_alloc, exit 3). Film fps had no upper bound.
TEST(SweepSpecReader, SeedsAreExactSixtyFourBitValuesAndFilmFpsIsBounded) {
  EXPECT_EQ(parseSweepSpec(studySpec("seeds: [9007199254740993, 18446744073709551615]\n"),
                           "spec.yaml", "")
                .seeds,
            (std::vector<std::uint64_t>{9007199254740993u, 18446744073709551615u}));
  EXPECT_EQ(parseSweepSpec(studySpec("seeds: {from: 18446744073709551614, to: "
                                     "18446744073709551615}\n"),
                           "spec.yaml", "")
                .seeds,
            (std::vector<std::uint64_t>{18446744073709551614u, 18446744073709551615u}));
  EXPECT_EQ(parseSweepSpec(studySpec("seeds: [1e3]\n"), "spec.yaml", "").seeds,
            (std::vector<std::uint64_t>{1000}));
  EXPECT_THAT(errorOf(studySpec("seeds: 18446744073709551616\n")),
              HasSubstr("seeds: must be a whole number in [0, 18446744073709551615]"));
  EXPECT_THAT(errorOf(studySpec("seeds: {from: 1, to: 1e12}\n")),
              HasSubstr("seeds.to: range too large"));
  EXPECT_THAT(errorOf(studySpec("tolerance: {max_contacts: 99999999999}\n")),
              HasSubstr("tolerance.max_contacts: must be at most 2147483647"));
  EXPECT_THAT(errorOf(studySpec("record: {film_failures: true, film: {fps: 1e9}}\n")),
              HasSubstr("record.film.fps: must be in (0, 1000] frames per second, got 1e9"));
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

}  // namespace sweep_spec_reader_test
}  // namespace parksim
