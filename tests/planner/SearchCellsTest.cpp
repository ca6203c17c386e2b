#include "parksim/planner/search/SearchCells.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <set>

#include "parksim/core/geometry/Angle.h"

namespace parksim {
namespace {

// A 1.8 x 1.2 m window from (0.5, -0.2): coarse cells of 0.1 m and 8 headings, fine ones of
// 0.025 m and 16 headings within 0.2 m of the one source.
const LotBounds kWindow{0.5, -0.2, 2.3, 1.0};
const Pose2 kSource{1.0, 0.4, 0.0};
constexpr std::int64_t kCoarseCells = (18 + 1) * (12 + 1) * 8;

SearchCells cells() { return SearchCells(kWindow, {0.1, 8}, {0.025, 16}, 0.2, {kSource}); }

TEST(SearchCells, CoarseKeysNumberEveryCellOfTheWindowOnce) {
  const SearchCells c = cells();
  std::set<std::int64_t> keys;
  for (int i = 0; i < 18; ++i) {
    for (int j = 0; j < 12; ++j) {
      for (int k = 0; k < 8; ++k) {
        const Pose2 p{kWindow.x_min_m + 0.1 * i + 0.05, kWindow.y_min_m + 0.1 * j + 0.05,
                      wrapAngle(k * kPi / 4.0)};
        const std::int64_t key = c.key(p);
        EXPECT_GE(key, 0);
        EXPECT_LT(key, kCoarseCells);
        keys.insert(key);
      }
    }
  }
  EXPECT_EQ(keys.size(), 18u * 12u * 8u);
  // Poses in one cell share its key; a heading of pi and of -pi are one heading.
  EXPECT_EQ(c.key({1.01, 0.41, 0.0}), c.key({1.04, 0.44, 0.1}));
  EXPECT_EQ(c.key({1.01, 0.41, kPi}), c.key({1.01, 0.41, -kPi}));
  EXPECT_NE(c.key({1.01, 0.41, 0.0}), c.key({1.11, 0.41, 0.0}));
}

TEST(SearchCells, TheFineZoneIsFinerNearASourceOnlyOnceOn) {
  SearchCells c = cells();
  const Pose2 near_a{1.05, 0.41, 0.0};
  const Pose2 near_b{1.08, 0.41, 0.0};  // same coarse cell, another fine one
  const Pose2 far{2.0, 0.9, 0.0};
  EXPECT_FALSE(c.inFineZone(near_a));
  EXPECT_EQ(c.key(near_a), c.key(near_b));
  const std::int64_t far_key = c.key(far);

  c.enableFineZone();
  EXPECT_TRUE(c.inFineZone(near_a));
  EXPECT_FALSE(c.inFineZone(far));
  EXPECT_GE(c.key(near_a), kCoarseCells);  // fine keys after every coarse one
  EXPECT_NE(c.key(near_a), c.key(near_b));
  EXPECT_EQ(c.key(far), far_key);  // outside the zone nothing changes

  // A finer level splits the fine cells again.
  const Pose2 near_c{1.051, 0.41, 0.0};
  EXPECT_EQ(c.key(near_a), c.key(near_c));
  c.setFine({0.0005, 32});
  EXPECT_NE(c.key(near_a), c.key(near_c));
}

TEST(SearchCells, NoFineZoneWhenItsRadiusIsZero) {
  SearchCells c(kWindow, {0.1, 8}, {0.025, 16}, 0.0, {kSource});
  c.enableFineZone();
  EXPECT_FALSE(c.inFineZone(kSource));
  EXPECT_LT(c.key(kSource), kCoarseCells);
  EXPECT_DOUBLE_EQ(c.width_m(), 1.8);
  EXPECT_DOUBLE_EQ(c.height_m(), 1.2);
}

}  // namespace
}  // namespace parksim
