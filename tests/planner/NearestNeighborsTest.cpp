#include "parksim/planner/tree/NearestNeighbors.h"

#include <limits>
#include <random>

#include <gtest/gtest.h>

namespace parksim {
namespace {

TEST(NearestNeighbors, MetricAddsChordsNotRadians) {
  const NearestNeighbors nn(0.1);
  EXPECT_NEAR(nn.distance({0, 0, 0}, {0.3, 0.4, 0}), 0.5, 1e-12);
  // Half a turn moves a point 0.1 m from the reference point by 0.2 m.
  EXPECT_NEAR(nn.distance({0, 0, 0}, {0, 0, kPi}), 0.2, 1e-12);
  EXPECT_NEAR(nn.distance({0, 0, kPi - 0.01}, {0, 0, -kPi + 0.01}), 2 * 0.1 * std::sin(0.01),
              1e-12);
}

TEST(NearestNeighbors, EqualsBruteForceWhileGrowing) {
  NearestNeighbors nn(0.082);
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> x(0, 1.8), y(0, 1.2), th(-kPi, kPi);
  std::vector<Pose2> poses;
  int checked = 0;
  for (int i = 0; i < 5000; ++i) {
    poses.push_back({x(rng), y(rng), th(rng)});
    EXPECT_EQ(nn.add(poses.back()), poses.size() - 1);
    if (i % 10 != 0) continue;
    for (int q = 0; q < 5; ++q) {
      const Pose2 query{x(rng), y(rng), th(rng)};
      std::size_t best = 0;
      double best_d = std::numeric_limits<double>::infinity();
      for (std::size_t k = 0; k < poses.size(); ++k) {
        const double d = nn.distance(query, poses[k]);
        if (d < best_d) best_d = d, best = k;
      }
      EXPECT_EQ(nn.nearest(query), best);
      const auto knn = nn.kNearest(query, 5);
      ASSERT_EQ(knn.size(), std::min<std::size_t>(5, poses.size()));
      EXPECT_EQ(knn[0], best);
      for (std::size_t k = 1; k < knn.size(); ++k) {
        EXPECT_LE(nn.distance(query, poses[knn[k - 1]]), nn.distance(query, poses[knn[k]]));
      }
      const double radius = 0.15;
      std::size_t inside = 0;
      for (const Pose2& p : poses) inside += nn.distance(query, p) < radius;
      EXPECT_EQ(nn.withinRadius(query, radius).size(), inside);
      ++checked;
    }
  }
  EXPECT_EQ(checked, 2500);
}

}  // namespace
}  // namespace parksim
