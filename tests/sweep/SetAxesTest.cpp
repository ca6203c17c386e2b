// set: axes and samples: in a sweep spec: any world value a --set names, and the planner's and
// controller's parameters, on a grid or drawn; their columns, ids, checks and the generator.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "parksim/core/io/Error.h"
#include "parksim/core/io/Fnv1a.h"
#include "parksim/core/io/NumberFormat.h"
#include "parksim/sweep/spec/EpisodeExpansion.h"
#include "parksim/sweep/spec/EpisodeSetup.h"
#include "parksim/sweep/spec/SetValues.h"
#include "parksim/sweep/spec/SweepSpecReader.h"
#include "tests/sweep/SweepTestSupport.h"

namespace parksim {
namespace {

using testing::studySpec;

std::vector<SweepEpisode> episodesOf(const std::string& axes, SweepSpec* spec_out = nullptr) {
  static SweepSpec spec;  // the episodes point at its tolerance
  spec = parseSweepSpec(studySpec(axes), "spec.yaml", "");
  if (spec_out != nullptr) *spec_out = spec;
  return expandEpisodes(spec, loadSweepWorlds(spec));
}

std::string errorOf(const std::string& axes) {
  try {
    (void)episodesOf(axes);
  } catch (const Error& e) {
    return e.what();
  }
  return "accepted";
}

// The example: two values of a robot limit, two episodes per other combination, each
// value in its own column, every id different, and the world each episode drives is the file's
// with the value applied.
TEST(SetAxes, AWorldValueOnAGridMultipliesTheEpisodes) {
  const std::vector<SweepEpisode> episodes =
      episodesOf("seeds: [1, 2]\nset: {robot.max_wheel_speed_radps: [6, 10]}\n");
  ASSERT_EQ(episodes.size(), 4u);
  std::set<std::string> ids;
  std::map<std::string, int> per_value;
  for (const SweepEpisode& e : episodes) {
    ids.insert(e.id);
    const std::string& v = e.params.world_set.at("robot.max_wheel_speed_radps");
    ++per_value[v];
    const auto world = episodeWorld(e.params, e.world);
    EXPECT_EQ(formatShortest(world->scenario.robot.max_wheel_speed_radps), v);
    EXPECT_EQ(world->scenario.name, "head_in");
    nlohmann::ordered_json row;
    appendParamColumns(e.params, row);
    EXPECT_EQ(row["robot.max_wheel_speed_radps"], std::stoi(v));
    EXPECT_FALSE(row.contains("sample"));
  }
  EXPECT_EQ(ids.size(), 4u);
  EXPECT_EQ(per_value, (std::map<std::string, int>{{"10", 2}, {"6", 2}}));
}

// Validated as --set validates it, before anything runs: one line naming the spec's line and
// the path.
TEST(SetAxes, ABadValueOrPathIsRefusedAtItsLineOfTheSpec) {
  // studySpec's three lines, then the axis: line 4 ("set:"), its path on line 5.
  EXPECT_EQ(errorOf("set:\n  robot.max_wheel_speed_radps: [6, -1]\n"),
            "spec.yaml:5: set: robot.max_wheel_speed_radps=-1: robot.max_wheel_speed_radps: must "
            "be positive, got -1");
  const std::string unknown = errorOf("set:\n  robot.wheel_size: [1]\n");
  EXPECT_EQ(unknown.rfind("spec.yaml:5: set: robot.wheel_size=1: ", 0), 0u) << unknown;
  EXPECT_NE(unknown.find("wheel_size"), std::string::npos) << unknown;
  const std::string list = errorOf("set:\n  obstacles[99].center: [[1, 1]]\n");
  EXPECT_EQ(list.rfind("spec.yaml:5: set: obstacles[99].center=[1,1]: ", 0), 0u) << list;
  // What the spec alone can tell is refused when it is read.
  const auto readError = [](const std::string& axes) {
    try {
      (void)parseSweepSpec(studySpec(axes), "spec.yaml", "");
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_EQ(readError("set:\n  realism: [1]\n").rfind("spec.yaml:5: set.realism: ", 0), 0u);
  EXPECT_EQ(readError("set:\n  name: [x]\n").rfind("spec.yaml:5: set.name: ", 0), 0u);
  EXPECT_EQ(
      readError("set:\n  planner.bad-name: [1]\n").rfind("spec.yaml:5: set.planner.bad-name", 0),
      0u);
  EXPECT_EQ(readError("set:\n  planner.k: [[1, 2]]\n").rfind("spec.yaml:5: set.planner.k[0]: ", 0),
            0u);
  EXPECT_EQ(readError("set:\n  robot.mass_kg: [1, 1.0]\n")
                .rfind("spec.yaml:5: set.robot.mass_kg[1]: repeats", 0),
            0u);
  EXPECT_EQ(readError("set:\n  robot.mass_kg: {uniform: [1, 2]}\n")
                .rfind("spec.yaml:5: set.robot.mass_kg: a distribution is drawn samples: times", 0),
            0u);
  EXPECT_EQ(readError("samples: {count: 3, seed: 1}\n").rfind("spec.yaml:4: samples: draws", 0),
            0u);
  EXPECT_EQ(readError("set:\n  robot.mass_kg: {uniform: [2, 1]}\nsamples: {count: 3, seed: 1}\n")
                .rfind("spec.yaml:5: set.robot.mass_kg.uniform: ", 0),
            0u);
  EXPECT_EQ(readError("realism: lab\nset:\n  realism.control.rate_hz: [30]\n")
                .rfind("spec.yaml:6: set.realism.control.rate_hz: ", 0),
            0u);
}

// Regression (issue 39): a wheel too light for Bullet to turn was refused only when the episode
// built its simulation, after planning, so a sweep stopped mid-way. Now the sweep refuses the
// point while it expands, before any episode runs. The least mass computed here: Bullet's
// single-precision epsilon over a solid sphere's 2/5 r^2 at the study's 20 mm wheels.
TEST(SetAxes, AWheelBulletCannotTurnIsRefusedBeforeAnyEpisodeRuns) {
  const double least_kg = 1.1920929e-7 / (0.4 * 0.02 * 0.02);
  EXPECT_NEAR(least_kg, 7.45e-4, 1e-6);
  const std::string e = errorOf("set:\n  physics.wheel_mass_kg: [0.02, 0.0005]\n");
  EXPECT_EQ(e.rfind("spec.yaml:5: set: physics.wheel_mass_kg=5e-04: ", 0), 0u) << e;
  EXPECT_NE(e.find("inertia about its axis, 8e-08 kg m^2"), std::string::npos) << e;
  EXPECT_NE(e.find("a wheel needs 0.000745 kg or more"), std::string::npos) << e;
  EXPECT_EQ(errorOf("set:\n  physics.wheel_mass_kg: [0.02, 0.001]\n"), "accepted");
}

std::vector<std::pair<std::string, std::string>> drawn(const std::vector<SweepEpisode>& episodes) {
  std::vector<std::pair<std::string, std::string>> out;
  for (const SweepEpisode& e : episodes) {
    out.emplace_back(e.id, canonicalString(e.params));
  }
  return out;
}

const char* kSampled =
    "set:\n"
    "  realism.control.rate_hz: {uniform: [20, 60]}\n"
    "  robot.max_wheel_speed_radps: {normal: [8, 0.5]}\n"
    "  realism.preset: {choice: [ideal, lab]}\n"
    "  tolerance.max_pos_err_m: [0.004, 0.006]\n"
    "samples: {count: 20, seed: 1}\n";

// The same spec, the same episodes: values and ids. Every sample draws each distribution once
// for each grid value; raising the count keeps the first draws.
TEST(SetAxes, SamplesAreTheSameEpisodesEveryTime) {
  const std::vector<SweepEpisode> a = episodesOf(kSampled);
  ASSERT_EQ(a.size(), 40u);
  EXPECT_EQ(drawn(a), drawn(episodesOf(kSampled)));
  std::set<std::string> ids;
  std::map<std::uint64_t, int> per_sample;
  for (const SweepEpisode& e : a) {
    ids.insert(e.id);
    ++per_sample[e.params.sample.value()];
    double rate = 0.0;
    ASSERT_TRUE(parseDouble(e.params.world_set.at("realism.control.rate_hz"), rate));
    EXPECT_GE(rate, 20.0);
    EXPECT_LT(rate, 60.0);
    const std::string& preset = e.params.world_set.at("realism.preset");
    EXPECT_TRUE(preset == "ideal" || preset == "lab") << preset;
    const auto world = episodeWorld(e.params, e.world);
    EXPECT_EQ(world->sections.realism.control.rate_hz, rate);
    // The preset's other values, then the drawn rate over them (the world's realism: section).
    EXPECT_EQ(world->sections.realism.pose_sensor.enabled, preset == "lab");
  }
  EXPECT_EQ(ids.size(), 40u);
  ASSERT_EQ(per_sample.size(), 20u);
  for (const auto& [sample, n] : per_sample) EXPECT_EQ(n, 2) << sample;
  // More samples: the first 20 are among them, unchanged.
  std::string more = kSampled;
  more.replace(more.find("count: 20"), 9, "count: 30");
  const std::vector<SweepEpisode> b = episodesOf(more);
  std::set<std::string> b_ids;
  for (const SweepEpisode& e : b) b_ids.insert(e.id);
  for (const std::string& id : ids) EXPECT_EQ(b_ids.count(id), 1u) << id;
  // Another seed draws other values.
  std::string other = kSampled;
  other.replace(other.find("seed: 1"), 7, "seed: 2");
  EXPECT_NE(drawn(episodesOf(other)), drawn(a));
}

// The generator as docs/sweeps.md and SetValues.h specify it, written again here from that
// text: what makes ids the same on any machine.
TEST(SetValues, TheGeneratorIsTheDocumentedOne) {
  const auto stream = [](std::uint64_t seed, std::uint64_t index, const std::string& path) {
    std::uint64_t state = fnv1a64("parksim-sample/1;" + std::to_string(seed) + ";" +
                                  std::to_string(index) + ";" + path);
    return [state]() mutable {
      std::uint64_t z = (state += 0x9E3779B97F4A7C15ULL);
      z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
      z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
      return static_cast<double>((z ^ (z >> 31)) >> 11) / 9007199254740992.0;
    };
  };
  const auto tenDigits = [](double v) {
    double out = 0.0;
    EXPECT_TRUE(parseDouble(formatGeneral(v, 10), out));
    return formatShortest(out);
  };
  const SampleDef samples{100, 7};
  SetDistribution uniform;
  uniform.kind = SetDistribution::Kind::kUniform;
  uniform.a = -1.0;
  uniform.b = 3.0;
  SetDistribution normal;
  normal.kind = SetDistribution::Kind::kNormal;
  normal.a = 10.0;
  normal.b = 2.0;
  SetDistribution choice;
  choice.kind = SetDistribution::Kind::kChoice;
  choice.choices = {"a", "b", "c"};
  std::map<std::string, int> chosen;
  for (std::uint64_t i = 0; i < samples.count; ++i) {
    auto u = stream(7, i, "x.u");
    EXPECT_EQ(drawSetValue(uniform, samples, i, "x.u"), tenDigits(-1.0 + 4.0 * u()));
    auto n = stream(7, i, "x.n");
    const double u1 = n();
    const double u2 = n();
    EXPECT_EQ(drawSetValue(normal, samples, i, "x.n"),
              tenDigits(10.0 + 2.0 * std::sqrt(-2.0 * std::log(1.0 - u1)) *
                                   std::cos(6.283185307179586 * u2)));
    auto c = stream(7, i, "x.c");
    const std::string pick = drawSetValue(choice, samples, i, "x.c");
    EXPECT_EQ(pick, choice.choices[static_cast<std::size_t>(3.0 * c())]);
    ++chosen[pick];
  }
  EXPECT_EQ(chosen.size(), 3u);  // 100 draws of three values: each drawn
}

// planner.NAME and controller.NAME reach the request as the planner's and the controller's
// parameters, columns by their paths.
TEST(SetAxes, PlannerAndControllerParametersReachTheRequest) {
  const std::vector<SweepEpisode> episodes =
      episodesOf("set:\n  planner.step_m: [0.05, 0.1]\n  controller.damping: 0.7\n");
  ASSERT_EQ(episodes.size(), 2u);
  for (const SweepEpisode& e : episodes) {
    const EpisodeRequest r = episodeRequest(e.params, episodeWorld(e.params, e.world), {});
    EXPECT_EQ(r.plan.planner_params, e.params.planner_params);
    EXPECT_EQ(r.controller_params, (ParamMap{{"damping", "0.7"}}));
    EXPECT_EQ(setColumnsOf(e.params),
              (std::vector<std::string>{"planner.step_m", "controller.damping"}));
    EXPECT_EQ(r.world.get(), &e.world->world);  // no world value: the shared world
  }
  EXPECT_NE(episodes[0].params.planner_params, episodes[1].params.planner_params);
  // A parameter the planner or controller does not have is refused when the spec expands, as
  // --planner-param would be: a typo is an error, not a default.
  EXPECT_THROW((void)episodesOf("set:\n  controller.gain: [1, 2]\n"), Error);
  EXPECT_THROW((void)episodesOf("set:\n  planner.step: [1, 2]\n"), Error);
}

}  // namespace
}  // namespace parksim
