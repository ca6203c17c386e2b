// Every tree planner with every steering, on the study lot head-in and parallel: over seeds it
// solves (basic RRT three in four, the others every seed), and each plan passes the independent
// checks. A rate over seeds is the assertion, so it runs once, in the Release pass (RELEASE in
// tests/planner/CMakeLists.txt); every planner with every steering runs under the sanitizers in
// planner_tests (TreePlannerTest.cpp: SameSeedSameResultForEveryPlannerAndSteering, with the
// same budgets, and the seed loops of its other tests).

#include <cstdint>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "parksim/planner/base/PlanScenario.h"
#include "tests/support/PlanChecks.h"
#include "tests/support/StudyLot.h"
#include "tests/support/TreePlannerSetup.h"

namespace parksim {
namespace tree_planner_study_lot {
namespace {

using testing::expectTreeRecorded;
using testing::expectValidPlan;
using testing::SatChecker;
using testing::treeSetupFor;

// RRT* spends its whole budget (testing::treeIterationBudget), so it gets fewer seeds.
int seedCount(const std::string& kind) { return kind == "rrt-star" ? 8 : 20; }

struct Case {
  std::string kind;
  SteeringKind steering;
  bool parallel;
};

std::string caseName(const ::testing::TestParamInfo<Case>& info) {
  std::string name = info.param.kind + "_" +
                     (info.param.steering == SteeringKind::kMoveToPose              ? "mtp"
                      : info.param.steering == SteeringKind::kRotateTranslateRotate ? "rtr"
                      : info.param.steering == SteeringKind::kReedsShepp            ? "rs"
                                                                                    : "bm") +
                     "_" + (info.param.parallel ? "parallel" : "head_in");
  for (char& c : name) c = c == '-' ? '_' : c;
  return name;
}

std::vector<Case> allCases() {
  std::vector<Case> cases;
  for (const std::string& kind : builtInPlanners().names()) {
    // Not tree planners: HardWorldsPlanningTest.cpp, TimeAStarTest.cpp.
    if (kind == "hybrid-a-star" || kind == "time-a-star" || kind == "car-a-star") continue;
    for (SteeringKind steering : allSteeringKinds()) {
      for (bool parallel : {false, true}) cases.push_back({kind, steering, parallel});
    }
  }
  return cases;
}

class TreePlannerOnStudyLot : public ::testing::TestWithParam<Case> {};

TEST_P(TreePlannerOnStudyLot, SolvesOverSeedsWithValidPlans) {
  const Case c = GetParam();
  const Scenario s = c.parallel ? testing::studyLotParallel() : testing::studyLot();
  const SatChecker checker(s);
  const int seeds = seedCount(c.kind);
  int solved = 0;
  for (int seed = 1; seed <= seeds; ++seed) {
    const PlanSetup setup = treeSetupFor(c.kind, c.steering, seed);
    const PlanResult r = planScenario(s, checker, setup);
    if (!r.solved()) continue;
    ++solved;
    SCOPED_TRACE("seed " + std::to_string(seed));
    expectValidPlan(s, checker, setup, r);
    expectTreeRecorded(r, 1);
    EXPECT_GT(r.stats.collision_queries, 0);
  }
  // Basic RRT only tries the goal near it and may run out of iterations; the others must solve
  // every seed.
  EXPECT_GE(solved, c.kind == "rrt" ? seeds * 3 / 4 : seeds);
}

INSTANTIATE_TEST_SUITE_P(Study, TreePlannerOnStudyLot, ::testing::ValuesIn(allCases()), caseName);

}  // namespace
}  // namespace tree_planner_study_lot
}  // namespace parksim
