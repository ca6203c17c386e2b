// SVG drawings as obstacles: shapes, transforms, holes by fill rule, the page's placement and
// scale, ids and layers, and what is refused.

#include "parksim/scenario/maps/SvgMap.h"

#include <cmath>

#include <gtest/gtest.h>

#include "parksim/core/io/Error.h"
#include "parksim/core/model/Geometry.h"
#include "tests/support/MapFiles.h"

namespace parksim {
namespace {

namespace fs = std::filesystem;

std::string svgDoc(
    const std::string& body,
    const std::string& size = "width=\"100mm\" height=\"50mm\" viewBox=\"0 0 100 50\"") {
  return "<?xml version=\"1.0\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" "
         "xmlns:inkscape=\"http://www.inkscape.org/namespaces/inkscape\" " +
         size + ">\n" + body + "\n</svg>\n";
}

SvgMapResult read(const fs::path& dir, const std::string& text, SvgMapDef def = {}) {
  testing::writeText(dir / "d.svg", text);
  def.path = (dir / "d.svg").string();
  def.prefix = "d";
  return readSvgMap(def);
}

std::string errorOf(const fs::path& dir, const std::string& text, SvgMapDef def = {}) {
  try {
    (void)read(dir, text, std::move(def));
  } catch (const Error& e) {
    return e.what();
  }
  return "(accepted)";
}

const Obstacle& named(const SvgMapResult& r, const std::string& name) {
  for (const Obstacle& o : r.obstacles) {
    if (o.name == name) return o;
  }
  throw std::runtime_error("no obstacle " + name);
}

TEST(SvgMap, ThePageLandsOnTheOriginWithYUpAtTheDrawingsScale) {
  const fs::path dir = testing::freshDir("svg_page");
  SvgMapDef def;
  def.origin = {2.0, 1.0};
  // A 10 x 5 mm box in the page's top-left corner (SVG's y points down).
  const SvgMapResult r =
      read(dir, svgDoc("<rect id=\"b\" x=\"0\" y=\"0\" width=\"10\" height=\"5\"/>"), def);
  EXPECT_TRUE(r.page.min().isApprox(Eigen::Vector2d(2.0, 1.0)));
  EXPECT_TRUE(r.page.max().isApprox(Eigen::Vector2d(2.1, 1.05)));
  const Obstacle& b = named(r, "d/b");
  EXPECT_EQ(b.shape, ObstacleShape::kBox);
  EXPECT_TRUE(b.box.center.isApprox(Eigen::Vector2d(2.005, 1.0475)));
  EXPECT_TRUE(b.box.half_extents.isApprox(Eigen::Vector2d(0.005, 0.0025)));
}

TEST(SvgMap, TransformsAreAppliedAndExactShapesStayExact) {
  const fs::path dir = testing::freshDir("svg_transforms");
  const SvgMapResult r =
      read(dir, svgDoc("<g transform=\"translate(50,25)\">"
                       "<circle id=\"c\" cx=\"0\" cy=\"0\" r=\"5\"/>"
                       "<g transform=\"rotate(30)\"><rect id=\"r\" x=\"-5\" y=\"-2\" width=\"10\" "
                       "height=\"4\"/></g>"
                       "<ellipse id=\"squashed\" cx=\"20\" cy=\"0\" rx=\"4\" ry=\"4\" "
                       "transform=\"scale(1,0.5)\"/>"
                       "</g>"));
  const Obstacle& c = named(r, "d/c");
  EXPECT_EQ(c.shape, ObstacleShape::kCircle);
  EXPECT_TRUE(c.box.center.isApprox(Eigen::Vector2d(0.05, 0.025)));
  EXPECT_NEAR(c.radius_m, 0.005, 1e-15);
  const Obstacle& rect = named(r, "d/r");
  EXPECT_EQ(rect.shape, ObstacleShape::kBox);
  // rotate(30) turns clockwise on the page (y down), so -30 degrees in the lot (y up).
  EXPECT_NEAR(
      std::remainder(rect.box.yaw + 30.0 * 3.14159265358979323846 / 180.0, 3.14159265358979323846),
      0.0, 1e-12);
  EXPECT_TRUE(rect.box.half_extents.isApprox(Eigen::Vector2d(0.005, 0.002)));
  // A circle squashed by a non-uniform scale is an ellipse: a polygon on it.
  const Obstacle& e = named(r, "d/squashed");
  EXPECT_EQ(e.shape, ObstacleShape::kPolygon);
  for (const Eigen::Vector2d& p : e.vertices) {
    const double u = (p.x() - 0.07) / 0.004;
    const double v = (p.y() - 0.025) / 0.002;
    EXPECT_NEAR(u * u + v * v, 1.0, 1e-9);
  }
}

TEST(SvgMap, PathsWithHolesByEitherFillRuleAndNonConvexOutlines) {
  const fs::path dir = testing::freshDir("svg_holes");
  const std::string square = "M 10 10 H 40 V 40 H 10 Z ";
  const SvgMapResult r =
      read(dir,
           svgDoc("<path id=\"evenodd\" fill-rule=\"evenodd\" d=\"" + square +
                      "M 20 20 H 30 V 30 H 20 Z\"/>"
                      "<path id=\"nonzero_same\" transform=\"translate(50,0)\" d=\"" +
                      square +
                      "M 20 20 H 30 V 30 H 20 Z\"/>"
                      "<path id=\"nonzero_opposite\" transform=\"translate(50,0)\" d=\"" +
                      "M 10 10 H 40 V 40 H 10 Z M 20 20 V 30 H 30 V 20 Z\"/>"
                      "<polygon id=\"ell\" points=\"0,0 8,0 8,2 2,2 2,8 0,8\"/>",
                  "viewBox=\"0 0 100 50\""),
           SvgMapDef{.scale = 0.01});
  const Obstacle& holed = named(r, "d/evenodd");
  ASSERT_EQ(holed.shape, ObstacleShape::kCompound);
  EXPECT_EQ(holed.compound->rings.size(), 2u);
  double area = 0.0;
  for (const auto& part : holed.compound->parts) area += 0.5 * signedDoubleArea(part);
  EXPECT_NEAR(area, 0.09 - 0.01, 1e-12);
  // Nonzero with both squares wound alike fills the inner one too: one convex square.
  EXPECT_EQ(named(r, "d/nonzero_same").shape, ObstacleShape::kPolygon);
  EXPECT_EQ(named(r, "d/nonzero_opposite").shape, ObstacleShape::kCompound);
  const Obstacle& ell = named(r, "d/ell");
  ASSERT_EQ(ell.shape, ObstacleShape::kCompound);
  EXPECT_EQ(ell.compound->parts.size(), 2u);
}

TEST(SvgMap, IdsAndLayersSelectTheObstaclesAndHiddenOrUndrawnElementsAreSkipped) {
  const fs::path dir = testing::freshDir("svg_select");
  const std::string doc = svgDoc(
      "<defs><rect id=\"template\" width=\"5\" height=\"5\"/></defs>"
      "<g inkscape:groupmode=\"layer\" inkscape:label=\"Walls\"><rect id=\"w\" width=\"5\" "
      "height=\"5\"/></g>"
      "<g inkscape:groupmode=\"layer\" inkscape:label=\"Notes\"><rect id=\"frame\" width=\"100\" "
      "height=\"50\"/><text x=\"1\" y=\"1\">note</text></g>"
      "<g id=\"cars\"><rect id=\"car\" x=\"50\" width=\"5\" height=\"5\"/></g>"
      "<rect id=\"hidden\" x=\"20\" width=\"5\" height=\"5\" style=\"display:none\"/>");
  EXPECT_EQ(read(dir, doc).obstacles.size(), 3u);  // w, frame, car
  SvgMapDef def;
  def.layers = {"Walls", "cars", "Roof"};
  def.ids = {"frame"};
  const SvgMapResult r = read(dir, doc, def);
  ASSERT_EQ(r.obstacles.size(), 3u);
  EXPECT_EQ(r.obstacles[0].name, "d/w");
  EXPECT_EQ(r.obstacles[1].name, "d/frame");
  EXPECT_EQ(r.obstacles[2].name, "d/car");
  EXPECT_EQ(r.layers_found, (std::vector<bool>{true, true, false}));
  EXPECT_EQ(r.ids_found, (std::vector<bool>{true}));
}

// The rectangle a wall drawn as a line covers, predicted from the drawing's numbers: the line
// from (x0, y0) to (x1, y1) on the page (mm, y down, a 50 mm high page), `w` mm wide, its ends
// out by w / 2.
void expectWall(const Obstacle& o, double x0, double y0, double x1, double y1, double w) {
  ASSERT_EQ(o.shape, ObstacleShape::kBox) << o.name;
  const Eigen::Vector2d a(x0 / 1000.0, (50.0 - y0) / 1000.0);
  const Eigen::Vector2d b(x1 / 1000.0, (50.0 - y1) / 1000.0);
  EXPECT_TRUE(o.box.center.isApprox(0.5 * (a + b), 1e-12)) << o.name;
  EXPECT_NEAR(o.box.half_extents.x(), 0.5 * (b - a).norm() + 0.5 * w / 1000.0, 1e-12) << o.name;
  EXPECT_NEAR(o.box.half_extents.y(), 0.5 * w / 1000.0, 1e-12) << o.name;
  // Its length along the line (either way round).
  const double along = std::atan2(b.y() - a.y(), b.x() - a.x());
  EXPECT_NEAR(std::remainder(o.box.yaw - along, 3.14159265358979323846), 0.0, 1e-12) << o.name;
}

TEST(SvgMap, WallsDrawnAsLinesAreAsThickAsTheirStroke) {
  const fs::path dir = testing::freshDir("svg_line_walls");
  // A floor plan's walls: two-point paths and polylines, a closed path on one line and a line,
  // stroke-width from the element, its style, its group or (none given) SVG's initial 1.
  const SvgMapResult r =
      read(dir, svgDoc("<g style=\"fill:none;stroke:#000;stroke-width:6\">"
                       "<path id=\"p\" d=\"M 10 10 L 40 10\" stroke-width=\"4\"/>"
                       "<polyline id=\"pl\" points=\"60,5 60,45\" style=\"stroke-width:2\"/>"
                       "<path id=\"closed\" d=\"M 10 30 L 50 30 L 20 30 Z\"/>"
                       "</g>"
                       "<line id=\"ln\" x1=\"70\" y1=\"10\" x2=\"90\" y2=\"30\"/>"
                       "<path id=\"h\" d=\"m 70 40 h 20\" style=\"stroke-width:inherit\"/>"
                       "<path id=\"dot\" d=\"M 5 5\"/>"));
  // Nothing with length is dropped; the lone point draws nothing.
  ASSERT_EQ(r.obstacles.size(), 5u);
  expectWall(named(r, "d/p"), 10, 10, 40, 10, 4);
  expectWall(named(r, "d/pl"), 60, 5, 60, 45, 2);
  expectWall(named(r, "d/closed"), 10, 30, 50, 30, 6);
  expectWall(named(r, "d/ln"), 70, 10, 90, 30, 1);
  expectWall(named(r, "d/h"), 70, 40, 90, 40, 1);
  EXPECT_EQ(r.parts, 5u);
}

TEST(SvgMap, LineWallsJoinOutlinesAndFollowTheirTransform) {
  const fs::path dir = testing::freshDir("svg_line_walls_mixed");
  const SvgMapResult r = read(
      dir, svgDoc("<path id=\"mix\" stroke-width=\"2\" d=\"M 0 0 H 10 V 10 H 0 Z M 20 5 L 40 5\"/>"
                  "<path id=\"corner\" stroke-width=\"2\" d=\"M 50 10 H 80 M 80 10 V 40\"/>"
                  "<path id=\"skewed\" stroke-width=\"2\" d=\"M 10 40 L 40 40\" "
                  "transform=\"skewX(30)\"/>"));
  const auto area = [](const std::vector<Eigen::Vector2d>& ring) {
    return 0.5 * signedDoubleArea(ring);
  };
  // An outline with area and a line: the square, and the 22 x 2 mm wall beside it.
  const Obstacle& mix = named(r, "d/mix");
  ASSERT_EQ(mix.shape, ObstacleShape::kCompound);
  ASSERT_EQ(mix.compound->parts.size(), 2u);
  EXPECT_NEAR(area(mix.compound->parts[0]), 100e-6, 1e-15);
  EXPECT_NEAR(area(mix.compound->parts[1]), 22 * 2e-6, 1e-15);
  // Two walls meeting at a corner: each 32 x 2 mm, overlapping there, the corner closed.
  const Obstacle& corner = named(r, "d/corner");
  ASSERT_EQ(corner.shape, ObstacleShape::kCompound);
  ASSERT_EQ(corner.compound->parts.size(), 2u);
  for (const auto& part : corner.compound->parts) {
    EXPECT_TRUE(isStrictlyConvexCcw(part));
    EXPECT_NEAR(area(part), 32 * 2e-6, 1e-15);
  }
  EXPECT_EQ(corner.compound->rings.size(), 2u);
  // Under a shear the wall is a parallelogram of the same area (skewX keeps areas).
  const Obstacle& skewed = named(r, "d/skewed");
  ASSERT_EQ(skewed.shape, ObstacleShape::kPolygon);
  ASSERT_EQ(skewed.vertices.size(), 4u);
  EXPECT_TRUE(isStrictlyConvexCcw(skewed.vertices));
  EXPECT_NEAR(area(skewed.vertices), 32 * 2e-6, 1e-15);
}

TEST(SvgMap, AStrokeWidthInUnitsRefusesOnlyAWallThatNeedsIt) {
  const fs::path dir = testing::freshDir("svg_stroke_units");
  // Shapes with area do not read their stroke.
  EXPECT_EQ(read(dir, svgDoc("<g style=\"stroke-width:0.5mm\"><rect width=\"5\" height=\"5\"/>"
                             "<path d=\"M 10 10 H 20 V 20 Z\"/></g>"))
                .obstacles.size(),
            2u);
}

TEST(SvgMap, RefusesWhatItCannotHonourInOneLocatedLine) {
  const fs::path dir = testing::freshDir("svg_bad");
  const std::string f = (dir / "d.svg").string();
  EXPECT_EQ(errorOf(dir, svgDoc("<path id=\"p\" d=\"M 0 0 L 5 5 X 2\"/>")),
            f + ":3: path#p: d: unknown path command 'X' at character 13 (near \"M 0 0 L 5 5 X "
                "2\")");
  EXPECT_EQ(errorOf(dir, svgDoc("<path id=\"bow\" d=\"M 0 0 L 10 10 L 10 0 L 0 20 Z\"/>")),
            f + ":3: path#bow: subpath 0 crosses or touches itself (edges from vertex 0 and "
                "vertex 2): a polygon must be simple");
  EXPECT_EQ(errorOf(dir, svgDoc("<path id=\"w\" d=\"M 0 0 L 5 5\" stroke-width=\"0\"/>")),
            f + ":3: path#w: stroke-width=\"0\": a wall drawn as a line (it has no area) is as "
                "thick as its stroke, which must be wider than 0");
  EXPECT_EQ(errorOf(dir, svgDoc("<g style=\"stroke-width:0.5mm\">\n<polyline points=\"0,0 5,0\"/>"
                                "</g>")),
            f + ":4: polyline: stroke-width=\"0.5mm\": a length in user units (a number, or px) "
                "is expected; other units and percentages are not supported");
  EXPECT_EQ(errorOf(dir, svgDoc("<line id=\"l\" x1=\"0\" y1=\"0\" x2=\"5\" y2=\"0\" "
                                "transform=\"matrix(1 0 0 1 0 0) scale(1,0)\"/>")),
            f + ":3: line#l: a wall drawn as a line has no area in the lot (its transform "
                "flattens it)");
  EXPECT_EQ(errorOf(dir, svgDoc("<use href=\"#a\"/>")),
            f + ":3: use: use elements are not supported; unlink the clone (Inkscape: Edit > "
                "Clone > Unlink Clone)");
  EXPECT_EQ(errorOf(dir, svgDoc("<rect width=\"10%\" height=\"5\"/>")),
            f + ":3: rect: width=\"10%\": a length in user units (a number, or px) is expected; "
                "other units and percentages are not supported");
  EXPECT_EQ(errorOf(dir, svgDoc("<g transform=\"spin(3)\"><rect width=\"1\" height=\"1\"/></g>")),
            f + ":3: g: transform: unknown transform 'spin' at character 1 (near \"spin(3)\")");
  EXPECT_EQ(errorOf(dir, svgDoc("<rect clip-path=\"url(#c)\" width=\"1\" height=\"1\"/>")),
            f + ":3: rect: clip-path is not supported on an obstacle shape");
  EXPECT_EQ(errorOf(dir, "<svg><rect></svg>").rfind(f + ":1: (XML): ", 0), 0u);
  EXPECT_EQ(errorOf(dir, svgDoc("<rect width=\"1\" height=\"1\"/>", "viewBox=\"0 0 10 10\"")),
            f + ": the drawing's width has no physical unit (mm, cm, in, pt, pc, px): give the "
                "map entry a scale (metres per user unit)");
}

}  // namespace
}  // namespace parksim
