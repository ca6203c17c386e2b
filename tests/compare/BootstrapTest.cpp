// The paired and unpaired bootstrap of quantiles: pairing, determinism.

#include "parksim/compare/Bootstrap.h"

#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "parksim/core/io/Error.h"

namespace parksim {
namespace {

TEST(Bootstrap, PairedResamplingCancelsWhatEpisodesShare) {
  std::mt19937_64 rng(7);
  std::vector<double> b;
  std::vector<double> c;
  std::normal_distribution<double> noise(0.0, 1.0);
  for (int i = 0; i < 20; ++i) {
    b.push_back(2.0 + noise(rng));
    c.push_back(1.2 * b.back());
  }
  std::mt19937_64 r1(1);
  const auto paired = bootstrapQuantiles(b, c, 0.5, true, 1000, r1);
  for (const QuantilePair& p : paired) EXPECT_NEAR(p.candidate, 1.2 * p.baseline, 1e-12);
  std::mt19937_64 r2(1);
  const auto unpaired = bootstrapQuantiles(b, c, 0.5, false, 1000, r2);
  int off = 0;
  for (const QuantilePair& p : unpaired) off += std::abs(p.candidate - 1.2 * p.baseline) > 1e-9;
  EXPECT_GT(off, 900);
}

TEST(Bootstrap, SameSeedSameReplicates) {
  const std::vector<double> b = {1, 2, 3, 4, 5, 6};
  const std::vector<double> c = {2, 3, 4, 5, 6, 7, 8};
  std::mt19937_64 r1(42);
  std::mt19937_64 r2(42);
  const auto x = bootstrapQuantiles(b, c, 0.95, false, 200, r1);
  const auto y = bootstrapQuantiles(b, c, 0.95, false, 200, r2);
  for (std::size_t i = 0; i < x.size(); ++i) {
    EXPECT_EQ(x[i].baseline, y[i].baseline);
    EXPECT_EQ(x[i].candidate, y[i].candidate);
  }
  EXPECT_THROW(bootstrapQuantiles(b, c, 0.5, true, 10, r1), Error);  // unequal lengths
  EXPECT_DOUBLE_EQ(percentileOf({1, 2, 3, 4, 5}, 0.5), 3.0);
}

}  // namespace
}  // namespace parksim
