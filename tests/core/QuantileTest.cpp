// Sample quantiles (type 7), as NumPy computes them.

#include "parksim/core/stats/Quantile.h"

#include <gtest/gtest.h>

#include "parksim/core/io/Error.h"

namespace parksim {
namespace {

TEST(Quantile, LinearBetweenOrderStatisticsAsNumpy) {
  // numpy.quantile([1, 2, 3, 4, 10], [0, 0.5, 0.95, 1]) = [1, 3, 8.8, 10]
  const std::vector<double> v = {10, 2, 4, 1, 3};
  EXPECT_DOUBLE_EQ(quantile7(v, 0.0), 1.0);
  EXPECT_DOUBLE_EQ(quantile7(v, 0.5), 3.0);
  EXPECT_DOUBLE_EQ(quantile7(v, 0.95), 8.8);
  EXPECT_DOUBLE_EQ(quantile7(v, 1.0), 10.0);
  EXPECT_DOUBLE_EQ(quantile7({7.0}, 0.95), 7.0);
  EXPECT_THROW(quantile7({}, 0.5), Error);
  EXPECT_THROW(quantile7({1.0}, 1.5), Error);
}

}  // namespace
}  // namespace parksim
