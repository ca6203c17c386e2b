#include "parksim/planner/motion/SpeedProfile.h"

#include <cmath>
#include <numeric>
#include <random>

#include <gtest/gtest.h>

#include "parksim/core/io/Error.h"

namespace parksim {
namespace {

// Sum, limits and half steps at both ends, for one profile.
void expectProfile(const std::vector<double>& u, double distance, double max_speed, double max_step,
                   double period) {
  const double covered = std::accumulate(u.begin(), u.end(), 0.0) * period;
  EXPECT_NEAR(covered, distance, 1e-12 * std::max(1.0, std::abs(distance)));
  ASSERT_FALSE(u.empty());
  EXPECT_LE(std::abs(u.front()), 0.5 * max_step + 1e-12);
  EXPECT_LE(std::abs(u.back()), 0.5 * max_step + 1e-12);
  for (std::size_t i = 0; i < u.size(); ++i) {
    EXPECT_LE(std::abs(u[i]), max_speed + 1e-12);
    EXPECT_GE(u[i] * distance, 0.0) << "speeds keep the distance's sign";
    if (i > 0) {
      EXPECT_LE(std::abs(u[i] - u[i - 1]), max_step + 1e-12);
    }
  }
}

TEST(SpeedProfile, CoversDistancesExactlyWithinLimits) {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> dist(-3.0, 3.0), lim(0.05, 2.0);
  for (int i = 0; i < 2000; ++i) {
    const double d = i % 10 == 0 ? 1e-7 * dist(rng) : dist(rng);
    const double v = lim(rng), a = lim(rng);
    expectProfile(restToRestProfile(d, v, a, 0.1), d, v, a, 0.1);
  }
}

TEST(SpeedProfile, UsesTheFewestPeriods) {
  // 0.2 m at 0.2 m/s top speed and 0.08 m/s per period: a full-speed trapezoid needs more than
  // 10 periods; one fewer period would not cover the distance even at the limits.
  const std::vector<double> u = restToRestProfile(0.2, 0.2, 0.08, 0.1);
  const std::vector<double> fewer = restToRestProfile(0.2 * 0.999, 0.2, 0.08, 0.1);
  EXPECT_LE(fewer.size(), u.size());
  double max_area = 0.0;  // of the unscaled trapezoid one period shorter
  const int n = static_cast<int>(u.size()) - 1;
  for (int i = 0; i < n; ++i) max_area += std::min({(i + 0.5) * 0.08, (n - i - 0.5) * 0.08, 0.2});
  EXPECT_LT(max_area * 0.1, 0.2);
}

TEST(SpeedProfile, ZeroDistanceIsEmptyAndBadLimitsThrow) {
  EXPECT_TRUE(restToRestProfile(0.0, 1.0, 1.0, 0.1).empty());
  EXPECT_THROW(restToRestProfile(1.0, 0.0, 1.0, 0.1), Error);
  EXPECT_THROW(restToRestProfile(1.0, 1.0, -1.0, 0.1), Error);
  EXPECT_THROW(restToRestProfile(std::nan(""), 1.0, 1.0, 0.1), Error);
}

TEST(SpeedProfile, EstimateIsWithinAFewPeriodsOfTheProfile) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> dist(1e-6, 50.0), lim(1e-3, 2.0);
  for (int i = 0; i < 300; ++i) {
    const double d = dist(rng), v = lim(rng), a = lim(rng);
    const double n = static_cast<double>(restToRestProfile(d, v, a, 0.1).size());
    EXPECT_NEAR(restToRestPeriods(d, v, a, 0.1), n, 3.0) << d << " " << v << " " << a;
  }
}

TEST(SpeedProfile, ProfilesBeyondTheLimitAreRefusedWithoutBeingBuilt) {
  // A tiny acceleration step used to take a quadratic search (hours); now it is refused by the
  // O(1) estimate, and the longest allowed profile is built in linear time.
  EXPECT_THROW(restToRestProfile(1.0, 10.0, 1e-9, 0.1), Error);
  EXPECT_THROW(restToRestProfile(1e9, 1.0, 1.0, 0.1), Error);
  const std::vector<double> longest =
      restToRestProfile(0.95 * kMaxProfilePeriods * 0.1, 1.0, 1.0, 0.1);
  EXPECT_LE(static_cast<double>(longest.size()), kMaxProfilePeriods);
  expectProfile(longest, 0.95 * kMaxProfilePeriods * 0.1, 1.0, 1.0, 0.1);
}

}  // namespace
}  // namespace parksim
