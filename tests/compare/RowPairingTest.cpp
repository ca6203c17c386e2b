// How compare groups and pairs rows: by report's group and the episode id by default; compared
// across the planner or the controller, by every other parameter column (the record's
// parameter fields and the set: columns, but world_file), the planner read as "*" in the
// group's name.

#include "parksim/compare/RowPairing.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "parksim/core/io/Error.h"
#include "parksim/sweep/spec/EpisodeParams.h"

namespace parksim {
namespace {

using Json = nlohmann::ordered_json;
using ::testing::HasSubstr;

// A row as a sweep writes its id and parameters, with an outcome after them.
Json rowOf(const EpisodeParams& p) {
  Json row;
  row["episode_id"] = episodeId(p);
  appendParamColumns(p, row);
  row["status"] = "met";
  row["max_pos_err_m"] = 1e-3;
  return row;
}

EpisodeParams headIn(std::uint64_t noise_seed) {
  EpisodeParams p;
  p.world = "head_in";
  p.world_file = "../worlds/head_in.yaml";
  p.realism = "lab";
  p.noise_seed = noise_seed;
  return p;
}

TEST(RowPairing, WithoutAcrossColumnsRowsPairByIdInReportsGroups) {
  const RowPairing pairing;
  const Json row = rowOf(headIn(3));
  EXPECT_EQ(pairing.pairKey(row), row["episode_id"].get<std::string>());
  EXPECT_EQ(pairing.groupKey(row), rowGroupKey(row));
}

TEST(RowPairing, AcrossThePlannerTheGroupNamesItStarAndRowsPairWithoutIt) {
  const RowPairing pairing({"planner"});
  EpisodeParams mine = headIn(3);
  mine.planner = "example";
  mine.smooth = true;
  EpisodeParams theirs = mine;
  theirs.planner = "time-a-star";
  const Json a = rowOf(mine);
  const Json b = rowOf(theirs);
  ASSERT_NE(a["episode_id"], b["episode_id"]);
  EXPECT_EQ(rowGroupName(pairing.groupKey(a)), "head_in / *+smooth / lab");
  EXPECT_EQ(pairing.groupKey(a), pairing.groupKey(b));
  EXPECT_EQ(pairing.pairKey(a), pairing.pairKey(b));
  // Every other parameter still tells episodes apart: the noise seed, a controller parameter.
  EXPECT_NE(pairing.pairKey(a), pairing.pairKey(rowOf(headIn(4))));
  EpisodeParams tuned_controller = mine;
  tuned_controller.controller_params["k"] = "1";
  EXPECT_NE(pairing.pairKey(a), pairing.pairKey(rowOf(tuned_controller)));
  // A planner's own parameters differ with the planner: across it, they do not count, and its
  // label leaves them out.
  EpisodeParams tuned = mine;
  tuned.planner_params["step_m"] = "0.1";
  EXPECT_EQ(pairing.pairKey(a), pairing.pairKey(rowOf(tuned)));
  EXPECT_EQ(pairing.groupKey(a), pairing.groupKey(rowOf(tuned)));
  EXPECT_NE(rowGroupKey(a), rowGroupKey(rowOf(tuned)));  // apart, two configurations
  // The world's file is provenance, as in ids: a baseline kept elsewhere still pairs.
  EpisodeParams moved = theirs;
  moved.world_file = "head_in.yaml";
  EXPECT_EQ(pairing.pairKey(a), pairing.pairKey(rowOf(moved)));
}

TEST(RowPairing, AcrossTheControllerGroupsMergeAndRowsPair) {
  const RowPairing pairing({"controller"});
  EpisodeParams mine = headIn(5);
  mine.controller = "pure-pursuit";
  const Json a = rowOf(mine);
  const Json b = rowOf(headIn(5));
  ASSERT_NE(a["episode_id"], b["episode_id"]);  // ";controller=pure-pursuit" in a's id
  // Apart, two controllers are two groups (the label names one that is not the default); across
  // the controller, one.
  EXPECT_NE(rowGroupKey(a), rowGroupKey(b));
  EXPECT_EQ(std::get<1>(rowGroupKey(a)), "time-a-star+smooth controller=pure-pursuit");
  EXPECT_EQ(pairing.groupKey(a), pairing.groupKey(b));
  EXPECT_EQ(pairing.groupKey(a), rowGroupKey(b));
  EXPECT_EQ(pairing.pairKey(a), pairing.pairKey(b));
  EXPECT_NE(RowPairing({"planner"}).pairKey(a), RowPairing({"planner"}).pairKey(b));
  EXPECT_EQ(RowPairing::valueText(a, "controller"), "pure-pursuit");
  EXPECT_EQ(RowPairing::valueText(a, "noise_seed"), "5");
  EXPECT_EQ(RowPairing::valueText(a, "controller.k"), "(none)");
}

TEST(RowPairing, OnlyPlannerAndControllerColumnsAreComparedAcross) {
  for (const char* ok : {"planner", "controller", "planner.step_m", "controller.k_x"}) {
    EXPECT_EQ(acrossColumnProblem(ok), "") << ok;
  }
  for (const char* bad : {"world", "seed", "noise_seed", "planner.", "", "robot.mass_kg"}) {
    EXPECT_THAT(acrossColumnProblem(bad),
                HasSubstr("(allowed: planner, controller, planner.NAME, controller.NAME)"))
        << bad;
  }
  try {
    (void)RowPairing({"planner", "seed"});
    FAIL() << "seed was accepted";
  } catch (const Error& e) {
    EXPECT_THAT(e.what(), HasSubstr("across: 'seed' is not a column to compare across"));
  }
  EXPECT_EQ(RowPairing({"planner", "planner"}).across(), std::vector<std::string>{"planner"});
}

}  // namespace
}  // namespace parksim
