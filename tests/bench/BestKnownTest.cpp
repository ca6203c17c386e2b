#include "bench/planning/BestKnown.h"

#include <gtest/gtest.h>

namespace parksim::bench {
namespace {

BenchRecord run(const std::string& planner, const std::string& scenario, double duration,
                bool valid = true) {
  BenchRecord r;
  r.library = "parksim";
  r.planner = planner;
  r.space = "balkcom-mason";
  r.scenario = scenario;
  r.budget = "iterations=10";
  r.solved = true;
  r.valid = valid;
  r.duration_s = duration;
  r.free_space_bound_s = 8.0;
  return r;
}

TEST(BestKnown, RatiosAgainstTheBestValidRunOrTheRecordedBest) {
  const std::vector<BenchRecord> records = {run("a", "w", 12.0), run("a", "w", 10.0),
                                            run("a", "w", 11.0), run("b", "w", 9.0, false),
                                            run("b", "w", 10.5)};
  // The invalid 9 s plan does not count: the best is 10 s.
  EXPECT_EQ(bestDurations(records).at("w"), 10.0);
  const std::vector<BestKnownRow> rows = compareWithBest(records);
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0].planner, "a");
  EXPECT_EQ(rows[0].duration_median_s, 11.0);
  EXPECT_NEAR(rows[0].over_best, 1.1, 1e-12);
  EXPECT_NEAR(rows[0].over_free_space, 11.0 / 8.0, 1e-12);
  EXPECT_EQ(rows[1].valid, 1);
  EXPECT_EQ(rows[1].duration_median_s, 10.5);
  // A shorter recorded best replaces the run's own; a longer one does not.
  EXPECT_NEAR(compareWithBest(records, {{"w", 8.8}})[0].over_best, 11.0 / 8.8, 1e-12);
  EXPECT_NEAR(compareWithBest(records, {{"w", 10.2}})[0].over_best, 1.1, 1e-12);
  EXPECT_NE(formatBestKnownTable(rows).find("| w | parksim | a |"), std::string::npos);
}

}  // namespace
}  // namespace parksim::bench
