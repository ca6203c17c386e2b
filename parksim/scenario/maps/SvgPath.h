#pragma once
// The two small grammars inside SVG attributes that an XML parser leaves as text: path data
// (`d`: M L H V C S Q T A Z, absolute and relative, implicit repeats) and transform lists
// (`matrix`, `translate`, `scale`, `rotate` with or without a centre, `skewX`, `skewY`), as
// SVG 1.1 defines them and Inkscape writes them, plus `points` lists. Curves and arcs are
// flattened into chords within a tolerance (their vertices lie on the curve). Strict: anything
// else throws SvgSyntaxError with what and where in the attribute, for the reader to locate in
// the file. Internal to the scenario module.

#include <cstddef>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>

namespace parksim {

/// A malformed or unsupported attribute value; the message says what, without the file.
class SvgSyntaxError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// An affine map [a c e; b d f] (SVG's matrix(a, b, c, d, e, f)).
struct SvgTransform {
  double a = 1.0, b = 0.0, c = 0.0, d = 1.0, e = 0.0, f = 0.0;

  Eigen::Vector2d apply(const Eigen::Vector2d& p) const {
    return {a * p.x() + c * p.y() + e, b * p.x() + d * p.y() + f};
  }
  /// This map after `inner`: p -> this(inner(p)).
  SvgTransform after(const SvgTransform& inner) const;
  /// The largest factor by which the map stretches a length (its largest singular value).
  double maxStretch() const;
  /// True when the map keeps shapes (rotation, uniform scale, translation, mirror): a circle
  /// stays a circle of radius r * scale() and a rectangle stays a rectangle.
  bool isSimilarity() const;
  /// The length scale of a similarity.
  double scale() const;
};

/// Parses a `transform` attribute ("translate(10,20) rotate(30 5 5)"). Empty text is the
/// identity.
SvgTransform parseSvgTransform(std::string_view text);

/// Parses path data and flattens it: one ring (list of points in user units, before any
/// transform) per subpath, each subpath taken as closed (the fill area's outline). Curves and
/// arcs are cut into chords whose distance from the curve is at most `tolerance` (at most 4096
/// chords a curve); more than `max_vertices` in all throws.
std::vector<std::vector<Eigen::Vector2d>> flattenSvgPath(std::string_view d, double tolerance,
                                                         std::size_t max_vertices);

/// Parses a `points` attribute (polygon, polyline): pairs of numbers.
std::vector<Eigen::Vector2d> parseSvgPoints(std::string_view text);

/// Points on the ellipse (cx, cy, rx, ry) from angle a0 to a1 (rad, both included), the
/// chords within `tolerance` of the curve.
std::vector<Eigen::Vector2d> svgEllipseArc(double cx, double cy, double rx, double ry, double a0,
                                           double a1, double tolerance);

/// A wall drawn as a line (`points`, in user units, all on one line and not all equal): the
/// rectangle its stroke covers, `width` user units wide, its ends out by half the width (as a
/// square cap draws them, so that walls meeting at a corner close it), carried into the lot by
/// `to_lot` (a parallelogram under a shear); counter-clockwise. Empty when the map flattens it.
std::vector<Eigen::Vector2d> svgLineStroke(const std::vector<Eigen::Vector2d>& points, double width,
                                           const SvgTransform& to_lot);

}  // namespace parksim
