#include "parksim/scenario/maps/SvgMap.h"

#include <libxml/parser.h>
#include <libxml/tree.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <memory>
#include <string_view>
#include <tuple>

#include "parksim/core/geometry/ConvexPartition.h"
#include "parksim/core/geometry/ExactOrientation.h"
#include "parksim/core/geometry/PolygonRegion.h"
#include "parksim/core/io/Error.h"
#include "parksim/core/io/InputFile.h"
#include "parksim/core/io/Text.h"
#include "parksim/core/model/Geometry.h"
#include "parksim/scenario/maps/MapLimits.h"
#include "parksim/scenario/maps/SvgPath.h"

namespace parksim {

namespace {

constexpr std::string_view kSvgNs = "http://www.w3.org/2000/svg";
constexpr const char* kInkscapeNs = "http://www.inkscape.org/namespaces/inkscape";
constexpr int kMaxSvgDepth = 256;

using Ring = std::vector<Eigen::Vector2d>;

struct XmlDocFree {
  void operator()(xmlDoc* d) const { xmlFreeDoc(d); }
};

std::string_view localName(const xmlNode* n) { return reinterpret_cast<const char*>(n->name); }

bool inSvgNamespace(const xmlNode* n) {
  return n->ns == nullptr || std::string_view(reinterpret_cast<const char*>(n->ns->href)) == kSvgNs;
}

std::optional<std::string> attribute(const xmlNode* n, const char* name) {
  xmlChar* v = xmlGetNoNsProp(n, reinterpret_cast<const xmlChar*>(name));
  if (v == nullptr) return std::nullopt;
  std::string out(reinterpret_cast<const char*>(v));
  xmlFree(v);
  return out;
}

std::optional<std::string> inkscapeAttribute(const xmlNode* n, const char* name) {
  xmlChar* v = xmlGetNsProp(n, reinterpret_cast<const xmlChar*>(name),
                            reinterpret_cast<const xmlChar*>(kInkscapeNs));
  if (v == nullptr) return std::nullopt;
  std::string out(reinterpret_cast<const char*>(v));
  xmlFree(v);
  return out;
}

std::string trimmed(std::string_view s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
  return std::string(s);
}

// A presentation property from the element's style attribute (which wins) or its attribute.
std::optional<std::string> property(const xmlNode* n, const std::string& name) {
  if (const auto style = attribute(n, "style")) {
    std::string_view rest = *style;
    while (!rest.empty()) {
      const std::size_t semi = rest.find(';');
      const std::string_view decl = rest.substr(0, semi);
      rest = semi == std::string_view::npos ? std::string_view() : rest.substr(semi + 1);
      const std::size_t colon = decl.find(':');
      if (colon == std::string_view::npos) continue;
      if (trimmed(decl.substr(0, colon)) == name) return trimmed(decl.substr(colon + 1));
    }
  }
  if (auto v = attribute(n, name.c_str())) return trimmed(*v);
  return std::nullopt;
}

// The element's own way of failing: "<file>:<line>: <tag>#<id>: <what>".
class SvgSite {
 public:
  SvgSite(const std::string& path, const xmlNode* node) : path_(path), node_(node) {}
  [[noreturn]] void fail(const std::string& what) const {
    std::string where = std::string(localName(node_));
    if (const auto id = attribute(node_, "id")) where += "#" + *id;
    throw Error(
        escapeText(path_ + ":" + std::to_string(xmlGetLineNo(node_)) + ": " + where + ": " + what));
  }

 private:
  const std::string& path_;
  const xmlNode* node_;
};

// A length in user units ("12", "12.5px"), the value of `name`; other units and percentages
// are refused.
double userLengthText(const SvgSite& site, const std::string& name, const std::string& text) {
  std::string s = trimmed(text);
  if (s.size() > 2 && s.compare(s.size() - 2, 2, "px") == 0) s.resize(s.size() - 2);
  double v = 0.0;
  const char* first = s.data() + (!s.empty() && s[0] == '+' ? 1 : 0);
  const auto [end, ec] = std::from_chars(first, s.data() + s.size(), v);
  if (ec != std::errc() || end != s.data() + s.size() || !std::isfinite(v)) {
    site.fail(name + "=\"" + text +
              "\": a length in user units (a number, or px) is expected; other units and "
              "percentages are not supported");
  }
  return v;
}

// A length attribute in user units, or `fallback` where the element has none.
double userLength(const SvgSite& site, const xmlNode* n, const char* name, double fallback) {
  const auto text = attribute(n, name);
  return text ? userLengthText(site, name, *text) : fallback;
}

// A root length with an optional unit, in metres per unit when the unit is physical.
struct RootLength {
  double value = 0.0;
  std::optional<double> metres_per_unit;  // set for mm, cm, in, pt, pc, px
};

std::optional<RootLength> rootLength(const std::string& path, const xmlNode* root,
                                     const char* name) {
  const auto text = attribute(root, name);
  if (!text) return std::nullopt;
  const std::string s = trimmed(*text);
  double v = 0.0;
  const auto [end, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
  const std::string unit(end, s.data() + s.size());
  RootLength out{v, std::nullopt};
  if (unit == "mm") out.metres_per_unit = 0.001;
  if (unit == "cm") out.metres_per_unit = 0.01;
  if (unit == "in") out.metres_per_unit = 0.0254;
  if (unit == "pt") out.metres_per_unit = 0.0254 / 72.0;
  if (unit == "pc") out.metres_per_unit = 0.0254 / 6.0;
  if (unit == "px") out.metres_per_unit = 0.0254 / 96.0;
  if (ec != std::errc() || !(v > 0.0) || !std::isfinite(v) ||
      (!unit.empty() && !out.metres_per_unit)) {
    SvgSite(path, root)
        .fail(std::string(name) + "=\"" + *text +
              "\": expected a positive length (a number with mm, cm, in, pt, pc, "
              "px or no unit)");
  }
  return out;
}

struct WalkState {
  SvgTransform ctm;  // user units of this element to the page's user units
  bool evenodd = false;
  bool selected = false;
  // The stroke-width in force (inherited), as written: read only where a wall is drawn as a
  // line, so that a width in units elsewhere refuses nothing.
  std::optional<std::string> stroke_width;
};

class SvgReader {
 public:
  SvgReader(const SvgMapDef& def, SvgMapResult& out) : def_(def), out_(out) {}

  void read() {
    const std::string bytes = readInputFile(def_.path, kMaxSvgFileBytes, "SVG drawing");
    xmlResetLastError();
    std::unique_ptr<xmlDoc, XmlDocFree> doc(
        xmlReadMemory(bytes.data(), static_cast<int>(bytes.size()), def_.path.c_str(), nullptr,
                      XML_PARSE_NONET | XML_PARSE_NOERROR | XML_PARSE_NOWARNING));
    if (!doc) {
      const xmlError* e = xmlGetLastError();
      std::string what = e && e->message ? e->message : "not well-formed XML";
      while (!what.empty() && (what.back() == '\n' || what.back() == ' ')) what.pop_back();
      throw Error(
          escapeText(def_.path + ":" + std::to_string(e ? e->line : 1) + ": (XML): " + what));
    }
    const xmlNode* root = xmlDocGetRootElement(doc.get());
    if (root == nullptr || localName(root) != "svg" || !inSvgNamespace(root)) {
      throw Error(escapeText(def_.path + ": not an SVG drawing (the root element is not svg)"));
    }
    placePage(root);
    out_.ids_found.assign(def_.ids.size(), false);
    out_.layers_found.assign(def_.layers.size(), false);
    WalkState state;
    state.selected = def_.ids.empty() && def_.layers.empty();
    walkChildren(root, state, 1);
  }

 private:
  // The root's viewBox and size: the page in user units, and the map from user units to the
  // lot (y flipped, the page's bottom-left corner on the origin).
  void placePage(const xmlNode* root) {
    const SvgSite site(def_.path, root);
    const std::optional<RootLength> width = rootLength(def_.path, root, "width");
    const std::optional<RootLength> height = rootLength(def_.path, root, "height");
    double x0 = 0.0, y0 = 0.0, w = 0.0, h = 0.0;
    if (const auto vb = attribute(root, "viewBox")) {
      std::vector<Eigen::Vector2d> numbers;
      try {
        numbers = parseSvgPoints(*vb);
      } catch (const SvgSyntaxError& e) {
        site.fail("viewBox: " + std::string(e.what()));
      }
      if (numbers.size() != 2 || !(numbers[1].x() > 0.0) || !(numbers[1].y() > 0.0)) {
        site.fail("viewBox=\"" + *vb + "\": expected min-x min-y width height, sizes > 0");
      }
      x0 = numbers[0].x();
      y0 = numbers[0].y();
      w = numbers[1].x();
      h = numbers[1].y();
    } else if (width && height) {
      // Without a viewBox the user unit is the CSS pixel.
      const double px = 0.0254 / 96.0;
      w = width->metres_per_unit ? width->value * *width->metres_per_unit / px : width->value;
      h = height->metres_per_unit ? height->value * *height->metres_per_unit / px : height->value;
    } else {
      site.fail("neither a viewBox nor a width and height: the page's size is unknown");
    }
    double scale = 0.0;
    if (def_.scale) {
      scale = *def_.scale;
    } else if (width && width->metres_per_unit) {
      scale = width->value * *width->metres_per_unit / w;
    } else {
      throw Error(escapeText(
          def_.path +
          ": the drawing's width has no physical unit (mm, cm, in, pt, pc, px): give the map "
          "entry a scale (metres per user unit)"));
    }
    page_ = {
        scale, 0.0, 0.0, -scale, def_.origin.x() - scale * x0, def_.origin.y() + scale * (y0 + h)};
    scale_ = scale;
    out_.page =
        Eigen::AlignedBox2d(def_.origin, def_.origin + Eigen::Vector2d(scale * w, scale * h));
  }

  bool matches(const std::vector<std::string>& names, std::vector<bool>& found,
               const std::optional<std::string>& name) {
    bool hit = false;
    for (std::size_t k = 0; name && k < names.size(); ++k) {
      if (names[k] == *name) {
        found[k] = true;
        hit = true;
      }
    }
    return hit;
  }

  void walkChildren(const xmlNode* parent, const WalkState& state, int depth) {
    for (const xmlNode* n = parent->children; n != nullptr; n = n->next) {
      if (n->type == XML_ELEMENT_NODE) walk(n, state, depth + 1);
    }
  }

  void walk(const xmlNode* n, WalkState state, int depth) {
    const SvgSite site(def_.path, n);
    if (depth > kMaxSvgDepth)
      site.fail("elements nest deeper than " + std::to_string(kMaxSvgDepth));
    if (!inSvgNamespace(n)) return;  // sodipodi:namedview, metadata of editors
    const std::string_view tag = localName(n);
    if (tag == "svg") site.fail("a nested svg element is not supported");
    static constexpr std::string_view kNotDrawn[] = {
        "defs",           "clipPath", "mask", "pattern", "marker",       "symbol",
        "metadata",       "title",    "desc", "style",   "script",       "linearGradient",
        "radialGradient", "filter",   "text", "image",   "foreignObject"};
    if (std::find(std::begin(kNotDrawn), std::end(kNotDrawn), tag) != std::end(kNotDrawn)) return;
    if (property(n, "display") == std::optional<std::string>("none")) return;
    const auto id = attribute(n, "id");
    if (matches(def_.ids, out_.ids_found, id)) state.selected = true;
    if (tag == "g" && !def_.layers.empty()) {
      const bool layer = inkscapeAttribute(n, "groupmode") == std::optional<std::string>("layer");
      if ((layer && matches(def_.layers, out_.layers_found, inkscapeAttribute(n, "label"))) ||
          matches(def_.layers, out_.layers_found, id)) {
        state.selected = true;
      }
    }
    if (const auto t = attribute(n, "transform")) {
      try {
        state.ctm = state.ctm.after(parseSvgTransform(*t));
      } catch (const SvgSyntaxError& e) {
        site.fail("transform: " + std::string(e.what()));
      }
    }
    if (const auto rule = property(n, "fill-rule")) {
      if (*rule == "evenodd")
        state.evenodd = true;
      else if (*rule == "nonzero")
        state.evenodd = false;
      else if (*rule != "inherit")
        site.fail("fill-rule: " + *rule + " is neither nonzero nor evenodd");
    }
    if (auto width = property(n, "stroke-width"); width && *width != "inherit") {
      state.stroke_width = std::move(width);
    }
    if (tag == "g" || tag == "a" || tag == "switch") {
      walkChildren(n, state, depth);
      return;
    }
    static constexpr std::string_view kShapes[] = {"path",    "rect",     "circle", "ellipse",
                                                   "polygon", "polyline", "line"};
    const bool shape = std::find(std::begin(kShapes), std::end(kShapes), tag) != std::end(kShapes);
    if (!state.selected) {
      if (!shape) walkChildren(n, state, depth);
      return;
    }
    if (tag == "use")
      site.fail(
          "use elements are not supported; unlink the clone (Inkscape: Edit > Clone > Unlink "
          "Clone)");
    if (!shape) {
      walkChildren(n, state, depth);
      return;
    }
    for (const char* p : {"clip-path", "mask"}) {
      const auto v = property(n, p);
      if (v && *v != "none") site.fail(std::string(p) + " is not supported on an obstacle shape");
    }
    if (++shapes_ > kMaxSvgShapes) {
      site.fail("more than " + std::to_string(kMaxSvgShapes) +
                " obstacle shapes in one drawing (docs/limits.md)");
    }
    readShape(n, site, tag, state);
  }

  std::string obstacleName(const xmlNode* n, std::string_view tag) {
    if (const auto id = attribute(n, "id")) return def_.prefix + "/" + *id;
    return def_.prefix + "/" + std::string(tag) + std::to_string(shapes_);
  }

  // The tolerance in the element's user units.
  double userTolerance(const WalkState& state) const {
    const double stretch = scale_ * state.ctm.maxStretch();
    return stretch > 0.0 ? def_.tolerance_m / stretch : def_.tolerance_m;
  }

  void readShape(const xmlNode* n, const SvgSite& site, std::string_view tag,
                 const WalkState& state) {
    const SvgTransform to_lot = page_.after(state.ctm);
    const std::string name = obstacleName(n, tag);
    const double tol = userTolerance(state);
    std::vector<Ring> rings;
    if (tag == "circle" || tag == "ellipse") {
      const double cx = userLength(site, n, "cx", 0.0);
      const double cy = userLength(site, n, "cy", 0.0);
      const double rx = userLength(site, n, tag == "circle" ? "r" : "rx", 0.0);
      const double ry = tag == "circle" ? rx : userLength(site, n, "ry", 0.0);
      if (rx < 0.0 || ry < 0.0) site.fail("a negative radius");
      if (rx == 0.0 || ry == 0.0) return;  // not rendered (SVG 1.1)
      if (rx == ry && to_lot.isSimilarity()) {
        addObstacle(
            Obstacle::makeCircle(name, def_.kind, {to_lot.apply({cx, cy}), rx * to_lot.scale()},
                                 def_.height_m),
            site, 1);
        return;
      }
      Ring ring = svgEllipseArc(cx, cy, rx, ry, 0.0, 2.0 * 3.14159265358979323846, tol);
      ring.pop_back();  // the end repeats the start
      rings.push_back(std::move(ring));
    } else if (tag == "rect") {
      const double x = userLength(site, n, "x", 0.0);
      const double y = userLength(site, n, "y", 0.0);
      const double w = userLength(site, n, "width", 0.0);
      const double h = userLength(site, n, "height", 0.0);
      if (w < 0.0 || h < 0.0) site.fail("a negative width or height");
      if (w == 0.0 || h == 0.0) return;  // not rendered (SVG 1.1)
      const bool has_rx = attribute(n, "rx").has_value();
      const bool has_ry = attribute(n, "ry").has_value();
      double rx = userLength(site, n, "rx", 0.0);
      double ry = userLength(site, n, "ry", 0.0);
      if (rx < 0.0 || ry < 0.0) site.fail("a negative corner radius");
      if (has_rx && !has_ry) ry = rx;
      if (has_ry && !has_rx) rx = ry;
      rx = std::min(rx, 0.5 * w);
      ry = std::min(ry, 0.5 * h);
      if (rx > 0.0 && ry > 0.0) {
        const double q = 0.5 * 3.14159265358979323846;
        Ring ring;
        for (const auto& [cx, cy, a] :
             {std::tuple{x + w - rx, y + ry, -q}, std::tuple{x + w - rx, y + h - ry, 0.0},
              std::tuple{x + rx, y + h - ry, q}, std::tuple{x + rx, y + ry, 2 * q}}) {
          for (const Eigen::Vector2d& p : svgEllipseArc(cx, cy, rx, ry, a, a + q, tol)) {
            if (ring.empty() || ring.back() != p) ring.push_back(p);
          }
        }
        rings.push_back(std::move(ring));
      } else if (to_lot.isSimilarity()) {
        OrientedBox box;
        box.center = to_lot.apply({x + 0.5 * w, y + 0.5 * h});
        box.half_extents = {0.5 * w * to_lot.scale(), 0.5 * h * to_lot.scale()};
        box.yaw = std::atan2(to_lot.b, to_lot.a);
        addObstacle(Obstacle::makeBox(name, def_.kind, box, def_.height_m), site, 1);
        return;
      } else {
        rings.push_back({{x, y}, {x + w, y}, {x + w, y + h}, {x, y + h}});
      }
    } else if (tag == "line") {
      rings.push_back({{userLength(site, n, "x1", 0.0), userLength(site, n, "y1", 0.0)},
                       {userLength(site, n, "x2", 0.0), userLength(site, n, "y2", 0.0)}});
    } else if (tag == "polygon" || tag == "polyline") {
      try {
        rings.push_back(parseSvgPoints(attribute(n, "points").value_or("")));
      } catch (const SvgSyntaxError& e) {
        site.fail("points: " + std::string(e.what()));
      }
    } else {  // path
      const auto d = attribute(n, "d");
      if (!d) site.fail("a path without d");
      try {
        rings = flattenSvgPath(*d, tol, kMaxSvgVertices - std::min(vertices_, kMaxSvgVertices));
      } catch (const SvgSyntaxError& e) {
        site.fail("d: " + std::string(e.what()));
      }
    }
    addRings(name, site, to_lot, std::move(rings), state);
  }

  void addObstacle(Obstacle o, const SvgSite& site, std::size_t parts) {
    if (!o.box.center.allFinite() || !(o.box.half_extents.minCoeff() >= 0.0)) {
      site.fail("its place in the lot is not a finite point");
    }
    out_.parts += parts;
    out_.obstacles.push_back(std::move(o));
  }

  // The thickness of a wall drawn as a line, in the shape's user units: the stroke-width in
  // force, else SVG's initial value, 1.
  static double wallThickness(const SvgSite& site, const WalkState& state) {
    if (!state.stroke_width) return 1.0;
    const double width = userLengthText(site, "stroke-width", *state.stroke_width);
    if (!(width > 0.0)) {
      site.fail("stroke-width=\"" + *state.stroke_width +
                "\": a wall drawn as a line (it has no area) is as thick as its stroke, which "
                "must be wider than 0");
    }
    return width;
  }

  // The rings in the lot, without repeated points; those with area filled by the fill rule,
  // those on one line walls as thick as their stroke (strokeOutline); one obstacle of them.
  void addRings(const std::string& name, const SvgSite& site, const SvgTransform& to_lot,
                std::vector<Ring> user_rings, const WalkState& state) {
    std::vector<Ring> rings;    // outlines with area
    std::vector<Ring> strokes;  // walls drawn as lines, convex
    for (Ring& r : user_rings) {
      Ring lot;
      for (const Eigen::Vector2d& p : r) {
        const Eigen::Vector2d q = to_lot.apply(p);
        if (!q.allFinite() || q.cwiseAbs().maxCoeff() > 1e4) {
          site.fail("a point lies beyond 10,000 m of the lot's origin");
        }
        if (lot.empty() || lot.back() != q) lot.push_back(q);
      }
      while (lot.size() > 1 && lot.back() == lot.front()) lot.pop_back();
      vertices_ += lot.size();
      if (vertices_ > kMaxSvgVertices) {
        site.fail("the drawing's shapes have more than " + std::to_string(kMaxSvgVertices) +
                  " vertices (docs/limits.md)");
      }
      // A ring on one line has no area (a figure eight's zero signed area is no excuse).
      bool flat = true;
      for (std::size_t k = 2; k < lot.size() && flat; ++k) {
        flat = orientation(lot[0], lot[1], lot[k]) == 0;
      }
      if (lot.size() >= 3 && !flat) {
        rings.push_back(std::move(lot));
      } else if (lot.size() >= 2) {
        Ring quad = svgLineStroke(r, wallThickness(site, state), to_lot);
        if (quad.empty()) {
          site.fail("a wall drawn as a line has no area in the lot (its transform flattens it)");
        }
        strokes.push_back(std::move(quad));
      }
      // One point has neither area nor length: SVG draws nothing there.
    }
    std::vector<PolygonWithHoles> regions;
    if (!rings.empty()) {
      if (const auto problem = ringsProblem(rings)) site.fail(*problem);
      regions = filledRegions(rings, state.evenodd);
    }
    if (strokes.empty() && regions.size() == 1 && regions[0].holes.empty()) {
      const PolygonWithHoles tidy = normalizedRegion(regions[0]);
      if (isStrictlyConvexCcw(tidy.outer)) {
        addObstacle(Obstacle::makePolygon(name, def_.kind, tidy.outer, def_.height_m), site, 1);
        return;
      }
    }
    if (regions.empty() && strokes.size() == 1) {
      const Ring& q = strokes.front();
      if (!to_lot.isSimilarity()) {
        addObstacle(Obstacle::makePolygon(name, def_.kind, q, def_.height_m), site, 1);
        return;
      }
      OrientedBox box;
      box.center = 0.5 * (q[0] + q[2]);
      box.half_extents = {0.5 * (q[1] - q[0]).norm(), 0.5 * (q[3] - q[0]).norm()};
      box.yaw = std::atan2(q[1].y() - q[0].y(), q[1].x() - q[0].x());
      addObstacle(Obstacle::makeBox(name, def_.kind, box, def_.height_m), site, 1);
      return;
    }
    std::vector<Ring> parts;
    std::vector<Ring> outline;
    for (const PolygonWithHoles& region : regions) {
      if (const auto problem = regionProblem(region)) site.fail(*problem);
      for (Ring& part : convexPartition(region)) parts.push_back(std::move(part));
      const PolygonWithHoles tidy = normalizedRegion(region);
      outline.push_back(tidy.outer);
      outline.insert(outline.end(), tidy.holes.begin(), tidy.holes.end());
    }
    // Walls drawn as lines are parts of their own, overlapping where they meet.
    for (const Ring& q : strokes) {
      parts.push_back(q);
      outline.push_back(q);
    }
    if (parts.empty()) return;
    const std::size_t count = parts.size();
    addObstacle(Obstacle::makeCompound(name, def_.kind,
                                       CompoundShape::make(std::move(parts), std::move(outline)),
                                       def_.height_m),
                site, count);
  }

  // Rings that neither cross nor touch nest; the area inside a ring is filled by the rule over
  // the rings around it. A ring whose inside is filled and outside not bounds a region; one
  // whose inside is not filled and outside is, a hole of the nearest region around it.
  static std::vector<PolygonWithHoles> filledRegions(const std::vector<Ring>& rings, bool evenodd) {
    const std::size_t n = rings.size();
    std::vector<std::vector<std::size_t>> around(n);  // rings containing ring i
    for (std::size_t i = 0; i < n; ++i) {
      for (std::size_t k = 0; k < n; ++k) {
        if (k != i && insideRegion({rings[k], {}}, rings[i].front())) around[i].push_back(k);
      }
    }
    const auto winding = [&](std::size_t i) { return signedDoubleArea(rings[i]) > 0.0 ? 1 : -1; };
    std::vector<int> outside_count(n, 0);  // winding (or depth) just outside ring i
    for (std::size_t i = 0; i < n; ++i) {
      for (std::size_t k : around[i]) outside_count[i] += evenodd ? 1 : winding(k);
    }
    const auto filled = [&](int w) { return evenodd ? (w % 2 != 0) : w != 0; };
    std::vector<int> region_of(n, -1);
    std::vector<PolygonWithHoles> regions;
    // Outer boundaries first (any order), then holes to the nearest enclosing region.
    for (std::size_t i = 0; i < n; ++i) {
      const int inside = outside_count[i] + (evenodd ? 1 : winding(i));
      if (filled(inside) && !filled(outside_count[i])) {
        region_of[i] = static_cast<int>(regions.size());
        regions.push_back({rings[i], {}});
      }
    }
    for (std::size_t i = 0; i < n; ++i) {
      const int inside = outside_count[i] + (evenodd ? 1 : winding(i));
      if (filled(inside) || !filled(outside_count[i])) continue;
      // The nearest region boundary around it: the one with the most rings around itself.
      int best = -1;
      std::size_t best_depth = 0;
      for (std::size_t k : around[i]) {
        if (region_of[k] >= 0 && (best < 0 || around[k].size() >= best_depth)) {
          best = region_of[k];
          best_depth = around[k].size();
        }
      }
      if (best >= 0) regions[static_cast<std::size_t>(best)].holes.push_back(rings[i]);
    }
    return regions;
  }

  const SvgMapDef& def_;
  SvgMapResult& out_;
  SvgTransform page_;
  double scale_ = 1.0;
  std::size_t shapes_ = 0;
  std::size_t vertices_ = 0;
};

}  // namespace

SvgMapResult readSvgMap(const SvgMapDef& def) {
  SvgMapResult out;
  SvgReader(def, out).read();
  return out;
}

}  // namespace parksim
