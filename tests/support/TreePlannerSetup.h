#pragma once
// Test support: the tree planners' set-up on the study lot, shared by planner_tests
// (TreePlannerTest.cpp, under the sanitizers) and study_planning_tests
// (TreePlannerStudyLotTest.cpp, the solve rates over seeds, in Release): one budget for both.

#include <cstdint>
#include <string>

#include <gtest/gtest.h>

#include "parksim/planner/base/PlanScenario.h"

namespace parksim::testing {

/// RRT* is anytime and spends its whole budget, so it gets fewer iterations; the others stop at
/// their first solution.
inline int treeIterationBudget(const std::string& kind) { return kind == "rrt-star" ? 150 : 2000; }

/// One planner with one steering and seed, unsmoothed: the tree planner alone
/// (PathSmootherTest.cpp tests smoothing).
inline PlanSetup treeSetupFor(const std::string& kind, SteeringKind steering, std::uint64_t seed) {
  PlanSetup setup;
  setup.planner = kind;
  setup.search.max_iterations = treeIterationBudget(kind);
  setup.search.seed = seed;
  setup.search.smooth = false;
  setup.steering_kind = steering;
  return setup;
}

/// Every tree edge is recorded: start-tree nodes but the start, goal-tree nodes but the roots.
inline void expectTreeRecorded(const PlanResult& r, int goal_roots) {
  EXPECT_EQ(static_cast<int>(r.tree_edges.size()),
            r.stats.tree_size - 1 + r.stats.goal_tree_size - goal_roots);
}

}  // namespace parksim::testing
