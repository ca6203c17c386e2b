#include "parksim/planner/search/SearchWindow.h"

#include <gtest/gtest.h>

namespace parksim {
namespace {

TEST(SearchWindow, TheProblemNotTheLotSetsTheWindow) {
  const LotBounds big{0.0, 0.0, 1000.0, 1000.0};
  const Pose2 a{500.0, 500.0, 0.0};
  const Pose2 b{503.0, 500.3, 1.0};
  const SearchWindowDef def;
  // Half the distance (1.5 m) beyond both, at least 0.5 m.
  EXPECT_NEAR(firstMargin(def, a, b), 0.5 * positionDistance(a, b), 1e-12);
  EXPECT_EQ(firstMargin(def, a, {500.1, 500.0, 0.0}), 0.5);
  const LotBounds w = searchWindow(big, a, b, 1.5);
  EXPECT_EQ(w.x_min_m, 498.5);
  EXPECT_EQ(w.y_max_m, 501.8);
  EXPECT_FALSE(coversLot(w, big));
  // Clipped to the lot; a margin past every edge is the lot.
  const LotBounds small{0.0, 0.0, 1.8, 1.2};
  EXPECT_TRUE(coversLot(searchWindow(small, {0.1, 0.1, 0}, {1.5, 0.04, 0}, 2.0), small));
  EXPECT_EQ(searchWindow(small, {0.1, 0.1, 0}, {0.2, 0.1, 0}, 0.5).x_min_m, 0.0);
}

}  // namespace
}  // namespace parksim
