// Fisher's and McNemar's exact tests against published and hand-computed values.

#include "parksim/compare/ExactTest.h"

#include <gtest/gtest.h>

#include "parksim/core/io/Error.h"

namespace parksim {
namespace {

TEST(ExactTest, FisherOneSidedMatchesTheTeaTastingTable) {
  // Fisher's lady tasting tea: 3 of 4 against 1 of 4; one-sided p = 17/70 (R: fisher.test(
  // matrix(c(3, 1, 1, 3), 2), alternative = "greater") gives 0.2429).
  EXPECT_NEAR(fisherLowerPValue(3, 4, 1, 4), 17.0 / 70.0, 1e-12);
  EXPECT_NEAR(fisherLowerPValue(4, 4, 0, 4), 1.0 / 70.0, 1e-12);
  EXPECT_DOUBLE_EQ(fisherLowerPValue(20, 20, 20, 20), 1.0);
  EXPECT_DOUBLE_EQ(fisherLowerPValue(0, 0, 3, 4), 1.0);
  // A better candidate is no evidence of a drop.
  EXPECT_GT(fisherLowerPValue(10, 20, 20, 20), 0.99);
  // 20/20 against 15/20: the candidate cannot meet fewer than 15, P = C(35,15) C(5,5) / C(40,20).
  EXPECT_NEAR(fisherLowerPValue(20, 20, 15, 20), 0.0235620235620, 1e-12);
  EXPECT_THROW(fisherLowerPValue(5, 4, 0, 4), Error);
}

TEST(ExactTest, McNemarIsABinomialTestOnDiscordantPairs) {
  EXPECT_DOUBLE_EQ(mcnemarWorsePValue(0, 0), 1.0);
  EXPECT_NEAR(mcnemarWorsePValue(5, 0), 1.0 / 32.0, 1e-15);
  EXPECT_NEAR(mcnemarWorsePValue(3, 1), 5.0 / 16.0, 1e-15);
  EXPECT_DOUBLE_EQ(mcnemarWorsePValue(0, 4), 1.0);
  EXPECT_NEAR(mcnemarWorsePValue(1000, 0), 0.0, 1e-300);  // no overflow
}

}  // namespace
}  // namespace parksim
