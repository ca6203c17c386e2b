// SVG path data and transform lists: the grammar as SVG 1.1 defines it, curves within their
// tolerance, and the refusals.

#include "parksim/scenario/maps/SvgPath.h"

#include <cmath>

#include <gtest/gtest.h>

namespace parksim {
// Named, not anonymous: its program is compiled as one unity batch, where another file's
// helpers of the same names would meet these.
namespace svg_path_test {

using Ring = std::vector<Eigen::Vector2d>;

std::vector<Ring> flat(std::string_view d, double tol = 0.01) {
  return flattenSvgPath(d, tol, 100000);
}

std::string errorOf(std::string_view d) {
  try {
    (void)flat(d);
  } catch (const SvgSyntaxError& e) {
    return e.what();
  }
  return "(accepted)";
}

TEST(SvgPath, LinesAbsoluteRelativeAndImplicit) {
  EXPECT_EQ(flat("M 0,0 L 10,0 10,10 Z"), (std::vector<Ring>{{{0, 0}, {10, 0}, {10, 10}}}));
  EXPECT_EQ(flat("m1 1 h 2 v 3 H 0z"), (std::vector<Ring>{{{1, 1}, {3, 1}, {3, 4}, {0, 4}}}));
  // Numbers packed as SVG allows: signs and dots separate them.
  EXPECT_EQ(flat("M0-1L.5.5-2e1,1e0"), (std::vector<Ring>{{{0, -1}, {0.5, 0.5}, {-20, 1}}}));
  // Two subpaths; the second's relative moveto starts from the first's start after z.
  EXPECT_EQ(flat("M 0 0 l 4 0 l 0 4 z m 1 1 l 1 0 l 0 1 z"),
            (std::vector<Ring>{{{0, 0}, {4, 0}, {4, 4}}, {{1, 1}, {2, 1}, {2, 2}}}));
}

TEST(SvgPath, CurvesAndArcsStayWithinTheTolerance) {
  // A half circle of radius 10 as an arc: every vertex on the circle, every chord within 0.01.
  const std::vector<Ring> arc = flat("M -10 0 A 10 10 0 0 0 10 0", 0.01);
  ASSERT_EQ(arc.size(), 1u);
  const Ring& r = arc[0];
  EXPECT_EQ(r.back(), Eigen::Vector2d(10, 0));
  for (std::size_t i = 0; i + 1 < r.size(); ++i) {
    EXPECT_NEAR(r[i].norm(), 10.0, 1e-9);
    EXPECT_LE(10.0 - (0.5 * (r[i] + r[i + 1])).norm(), 0.01 + 1e-12);
    EXPECT_GT(r[i].y(), -1e-9);  // sweep 0: angles decreasing from 180 to 0 degrees, y >= 0
  }
  EXPECT_GT(r.size(), 20u);
  // A cubic: the chords' midpoints stay within the tolerance of the exact curve.
  const Eigen::Vector2d p0(0, 0), p1(0, 10), p2(10, 10), p3(10, 0);
  const Ring c = flat("M 0 0 C 0 10 10 10 10 0", 0.05)[0];
  const auto bezier = [&](double t) {
    const double u = 1 - t;
    return Eigen::Vector2d(u * u * u * p0 + 3 * u * u * t * p1 + 3 * u * t * t * p2 +
                           t * t * t * p3);
  };
  for (std::size_t i = 0; i + 1 < c.size(); ++i) {
    const double t = (i + 0.5) / (c.size() - 1);
    EXPECT_LE((0.5 * (c[i] + c[i + 1]) - bezier(t)).norm(), 0.05);
  }
  // S reflects the previous control point: the same curve as C written out.
  EXPECT_EQ(flat("M 0 0 C 0 10 5 10 5 5 S 10 0 10 0"),
            flat("M 0 0 C 0 10 5 10 5 5 C 5 0 10 0 10 0"));
  EXPECT_EQ(flat("M 0 0 Q 5 10 10 0 T 20 0"), flat("M 0 0 Q 5 10 10 0 Q 15 -10 20 0"));
}

TEST(SvgPath, RefusesMalformedDataSayingWhere) {
  EXPECT_EQ(errorOf("L 0 0"),
            "path data must start with a moveto (M or m) at character 1 (near \"L 0 0\")");
  EXPECT_EQ(errorOf("M 0 0 X 1 1"),
            "unknown path command 'X' at character 7 (near \"M 0 0 X 1 1\")");
  EXPECT_EQ(errorOf("M 0 0 L 1"),
            "expected a number (lineto) at character 10 (near \"M 0 0 L 1\")");
  EXPECT_EQ(errorOf("M 0 0 A 1 1 0 2 0 1 1"),
            "expected an arc flag 0 or 1 at character 15 (near \"0 0 A 1 1 0 2 0 1 1\")");
  EXPECT_EQ(errorOf("M 0 0 L 1 1 Z 3"),
            "numbers after a closepath (Z) at character 15 (near \"0 0 L 1 1 Z 3\")");
  // A curve cut finer than the budget allows.
  EXPECT_THROW(flattenSvgPath("M 0 0 A 1 1 0 1 0 0 2", 1e-12, 1000), SvgSyntaxError);
}

TEST(SvgPath, TransformListsComposeLeftToRight) {
  const SvgTransform t = parseSvgTransform("translate(10,20) rotate(90) scale(2)");
  const Eigen::Vector2d p = t.apply({1, 0});  // scaled to (2, 0), turned to (0, 2), moved
  EXPECT_NEAR(p.x(), 10.0, 1e-12);
  EXPECT_NEAR(p.y(), 22.0, 1e-12);
  const Eigen::Vector2d q = parseSvgTransform("rotate(180 5 5)").apply({0, 0});
  EXPECT_NEAR(q.x(), 10.0, 1e-12);
  EXPECT_NEAR(q.y(), 10.0, 1e-12);
  const SvgTransform m = parseSvgTransform("matrix(1 2 3 4 5 6)");
  EXPECT_EQ(m.apply({1, 1}), Eigen::Vector2d(9, 12));
  EXPECT_NEAR(parseSvgTransform("skewX(45)").apply({0, 1}).x(), 1.0, 1e-12);
  EXPECT_TRUE(parseSvgTransform("rotate(30) scale(-2, 2)").isSimilarity());
  EXPECT_FALSE(parseSvgTransform("scale(1, 2)").isSimilarity());
  EXPECT_NEAR(parseSvgTransform("scale(1, 3)").maxStretch(), 3.0, 1e-12);
  EXPECT_THROW(parseSvgTransform("perspective(2)"), SvgSyntaxError);
  EXPECT_THROW(parseSvgTransform("rotate(1, 2)"), SvgSyntaxError);
  EXPECT_THROW(parseSvgTransform("translate(1"), SvgSyntaxError);
}

}  // namespace svg_path_test
}  // namespace parksim
