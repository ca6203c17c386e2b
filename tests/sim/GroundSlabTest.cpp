// The ground slab's size: the lot plus a metre, or in a large lot the region the robot drives in.

#include "parksim/sim/world/GroundSlab.h"

#include <gtest/gtest.h>

namespace parksim {
namespace {

TEST(GroundSlab, IsTheLotPlusAMetreWithoutAReach) {
  const GroundSlab g = groundSlab({0.0, 0.0, 1.8, 1.2}, std::nullopt, 3.0);
  EXPECT_DOUBLE_EQ(g.center.x(), 0.9);
  EXPECT_DOUBLE_EQ(g.center.y(), 0.6);
  EXPECT_DOUBLE_EQ(g.half_extents.x(), 1.9);
  EXPECT_DOUBLE_EQ(g.half_extents.y(), 1.6);
  EXPECT_DOUBLE_EQ(g.half_thickness_m, 0.05);
}

TEST(GroundSlab, AReachCoveringTheLotKeepsTheLotPlusAMetre) {
  // The study lots: a plan anywhere in a 1.8 m lot plus 3 m covers the whole lot plus 1 m.
  const LotBounds lot{0.0, 0.0, 1.8, 1.2};
  const GroundSlab g = groundSlab(lot, LotBounds{0.2, 0.3, 1.5, 0.9}, 3.0);
  const GroundSlab whole = groundSlab(lot, std::nullopt, 3.0);
  EXPECT_EQ(g.center, whole.center);
  EXPECT_EQ(g.half_extents, whole.half_extents);
}

TEST(GroundSlab, InALargeLotSpansTheReachPlusTheMarginClippedToTheLot) {
  const LotBounds lot{0.0, 0.0, 200.0, 200.0};
  const GroundSlab g = groundSlab(lot, LotBounds{10.0, 197.0, 12.0, 199.0}, 3.0);
  // x: 7 .. 15; y: 194 .. 201 (the lot plus 1 m ends there).
  EXPECT_DOUBLE_EQ(g.center.x(), 11.0);
  EXPECT_DOUBLE_EQ(g.half_extents.x(), 4.0);
  EXPECT_DOUBLE_EQ(g.center.y(), 197.5);
  EXPECT_DOUBLE_EQ(g.half_extents.y(), 3.5);
}

}  // namespace
}  // namespace parksim
