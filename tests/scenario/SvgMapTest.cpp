// SVG drawings as obstacles: shapes, transforms, holes by fill rule, the page's placement and
// scale, ids and layers, and what is refused.

#include "parksim/scenario/maps/SvgMap.h"

#include <cmath>

#include <gtest/gtest.h>

#include "parksim/core/io/Error.h"
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

TEST(SvgMap, RefusesWhatItCannotHonourInOneLocatedLine) {
  const fs::path dir = testing::freshDir("svg_bad");
  const std::string f = (dir / "d.svg").string();
  EXPECT_EQ(errorOf(dir, svgDoc("<path id=\"p\" d=\"M 0 0 L 5 5 X 2\"/>")),
            f + ":3: path#p: d: unknown path command 'X' at character 13 (near \"M 0 0 L 5 5 X "
                "2\")");
  EXPECT_EQ(errorOf(dir, svgDoc("<path id=\"bow\" d=\"M 0 0 L 10 10 L 10 0 L 0 20 Z\"/>")),
            f + ":3: path#bow: subpath 0 crosses or touches itself (edges from vertex 0 and "
                "vertex 2): a polygon must be simple");
  EXPECT_EQ(errorOf(dir, svgDoc("<line x1=\"0\" y1=\"0\" x2=\"5\" y2=\"5\"/>")),
            f + ":3: line: a line has no area; draw walls as rectangles or closed paths");
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
