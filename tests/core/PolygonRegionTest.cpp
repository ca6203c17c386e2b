#include "parksim/core/geometry/PolygonRegion.h"

#include <cmath>
#include <random>
#include <string>

#include <gtest/gtest.h>

#include "parksim/core/geometry/ExactOrientation.h"

namespace parksim {
namespace {

using Ring = std::vector<Eigen::Vector2d>;
__extension__ typedef __int128 Int128;  // exact products of 41-bit integers

std::string problem(const PolygonWithHoles& r) { return regionProblem(r).value_or("none"); }

TEST(PolygonRegion, OrientationIsExactWhereDoubleArithmeticIsNot) {
  // Points on a fine grid near the line y = x: the exact sign, from integer arithmetic on the
  // grid indices, against the predicate.
  std::mt19937_64 rng(3);
  const double unit = std::ldexp(1.0, -40);
  std::uniform_int_distribution<long long> jitter(-4, 4);
  std::uniform_int_distribution<long long> along(1, 1LL << 40);
  int zeros = 0;
  for (int k = 0; k < 20000; ++k) {
    long long ax = along(rng), bx = along(rng), cx = along(rng);
    long long ay = ax + jitter(rng), by = bx + jitter(rng), cy = cx + jitter(rng);
    const Int128 exact =
        static_cast<Int128>(bx - ax) * (cy - ay) - static_cast<Int128>(by - ay) * (cx - ax);
    const int sign = exact > 0 ? 1 : exact < 0 ? -1 : 0;
    zeros += sign == 0;
    ASSERT_EQ(orientation({ax * unit, ay * unit}, {bx * unit, by * unit}, {cx * unit, cy * unit}),
              sign);
  }
  EXPECT_GT(zeros, 100);
}

TEST(PolygonRegion, AcceptsSimplePolygonsWithHoles) {
  EXPECT_EQ(problem({{{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}}, {}}), "none");
  EXPECT_EQ(problem({{{0, 0}, {4, 0}, {4, 4}, {0, 4}},
                     {{{1, 1}, {2, 1}, {2, 2}}, {{3, 3}, {3.5, 3}, {3.5, 3.5}}}}),
            "none");
}

TEST(PolygonRegion, NamesWhatIsWrong) {
  EXPECT_EQ(problem({{{0, 0}, {1, 1}, {1, 0}, {0, 1}}, {}}),
            "the outline crosses or touches itself (edges from vertex 0 and vertex 2): a polygon "
            "must be simple");
  EXPECT_EQ(problem({{{0, 0}, {1, 0}, {1, 0}, {0, 1}}, {}}),
            "the outline, vertex 2: repeats the vertex before it");
  EXPECT_EQ(problem({{{0, 0}, {1, 0}, {2, 0}}, {}}),
            "the outline has no area: its vertices lie on one line");
  EXPECT_EQ(problem({{{0, 0}, {1, 0}}, {}}),
            "the outline has 2 vertices; a polygon needs at least 3");
  EXPECT_EQ(problem({{{0, 0}, {4, 0}, {4, 4}, {0, 4}}, {{{5, 5}, {6, 5}, {6, 6}}}}),
            "hole 0 lies outside the outline");
  EXPECT_EQ(problem({{{0, 0}, {4, 0}, {4, 4}, {0, 4}}, {{{0, 0}, {1, 1}, {1, 2}}}}),
            "the outline and hole 0 cross or touch each other");
  EXPECT_EQ(problem({{{0, 0}, {4, 0}, {4, 4}, {0, 4}},
                     {{{1, 1}, {3, 1}, {3, 3}, {1, 3}}, {{1.5, 1.5}, {2, 1.5}, {2, 2}}}}),
            "hole 1 lies inside hole 0; holes may not nest");
  EXPECT_EQ(problem({{{0, 0}, {4, 0}, {4, 4}, {2, 0}}, {}}),
            "the outline, vertex 0: the outline folds back on itself there");
  EXPECT_EQ(problem({{{0, 0}, {1, 0}, {std::nan(""), 1}}, {}}),
            "the outline, vertex 2: not a finite point");
  Ring many;
  for (std::size_t i = 0; i <= kMaxPolygonRegionVertices; ++i) {
    const double a = 2.0 * 3.14159265358979323846 * static_cast<double>(i) /
                     static_cast<double>(kMaxPolygonRegionVertices + 1);
    many.emplace_back(std::cos(a), std::sin(a));
  }
  EXPECT_EQ(problem({many, {}}),
            "has 20001 vertices; a polygon may have at most 20000 (holes included; "
            "docs/limits.md)");
}

TEST(PolygonRegion, NormalizingDropsCollinearVerticesAndWindsRings) {
  const PolygonWithHoles r = normalizedRegion(
      {{{0, 0}, {0, 4}, {4, 4}, {4, 2}, {4, 0}}, {{{1, 1}, {2, 1}, {2, 2}, {1, 2}}}});
  EXPECT_EQ(r.outer, (Ring{{0, 0}, {4, 0}, {4, 4}, {0, 4}}));
  EXPECT_EQ(r.holes[0], (Ring{{1, 1}, {1, 2}, {2, 2}, {2, 1}}));
  EXPECT_DOUBLE_EQ(regionDoubleArea(r), 2.0 * 15.0);
  EXPECT_TRUE(insideRegion(r, {0.5, 0.5}));
  EXPECT_FALSE(insideRegion(r, {1.5, 1.5}));
  EXPECT_TRUE(insideRegion(r, {1.0, 1.5}));  // on the hole's edge
  EXPECT_FALSE(insideRegion(r, {5.0, 1.0}));
}

}  // namespace
}  // namespace parksim
