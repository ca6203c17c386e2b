// Holm's step-down correction on Holm's own kind of example.

#include "parksim/compare/HolmCorrection.h"

#include <gtest/gtest.h>

namespace parksim {
namespace {

TEST(HolmCorrection, StepDownAdjustedInInputOrder) {
  // Holm (1979) on 0.01, 0.04, 0.03, 0.005 (m = 4): sorted 0.005*4, 0.01*3, 0.03*2, 0.04*1.
  const std::vector<double> adj = holmAdjusted({0.01, 0.04, 0.03, 0.005});
  EXPECT_DOUBLE_EQ(adj[3], 0.02);
  EXPECT_DOUBLE_EQ(adj[0], 0.03);
  EXPECT_DOUBLE_EQ(adj[2], 0.06);
  EXPECT_DOUBLE_EQ(adj[1], 0.06);  // monotone: never below an earlier step
  EXPECT_DOUBLE_EQ(holmAdjusted({0.5, 0.9})[1], 1.0);
  EXPECT_TRUE(holmAdjusted({}).empty());
}

}  // namespace
}  // namespace parksim
