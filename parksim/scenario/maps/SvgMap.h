#pragma once
// An SVG drawing as obstacles: the planning benchmarks' lots and warehouses, or a lot drawn in
// Inkscape. The XML is parsed by libxml2; every selected path, polygon, polyline, rect, circle,
// ellipse and line becomes one obstacle, with the transforms of its element and its groups
// applied as Inkscape writes them. A shape is solid: its outline's area (subpaths by its fill
// rule, so a path may have holes) is the obstacle, whatever its fill or stroke paint. A wall
// drawn as a line (a line element, a path or polyline of two points, a closed path on one line:
// no area) is as thick as its stroke: the rectangle its stroke-width covers (SVG's initial 1
// user unit where none is given), its ends out by half the width (svgLineStroke); nothing
// with length is dropped. The page's
// bottom-left corner lands on `origin` in the lot, x to the right and y up, at `scale` metres
// per user unit. Circles and rectangles under a transform that keeps shapes stay exact circles
// and boxes; curves, arcs and ellipses are flattened with vertices on the curve, within
// `tolerance_m`. Internal to the scenario module.
//
// Refused, in one line naming the file, the element's line and what it cannot honour: a
// selected `use` or nested `svg`; a clip-path or mask on a selected shape; lengths in units
// other than user units (px) or percentages; malformed path data or transforms; shapes whose
// outline crosses itself or another subpath; a wall drawn as a line whose stroke-width is 0;
// drawings beyond the limits of MapLimits.h. Not drawn, so not read: `defs`, `clipPath`,
// `mask`, `pattern`, `marker`, `symbol`, metadata, text, images, elements with display:none,
// rects of zero width or height, circles and ellipses of zero radius and subpaths of one
// point (SVG draws none of them).

#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "parksim/core/model/Scenario.h"

namespace parksim {

struct SvgMapDef {
  std::string path;    ///< the .svg file
  std::string prefix;  ///< obstacle names are "<prefix>/<element id>" (or "<prefix>/<tag><n>")
  ObstacleKind kind = ObstacleKind::kWall;
  double height_m = 0.1;
  /// Metres per user unit; unset: from the root's width with a unit and its viewBox.
  std::optional<double> scale;
  Eigen::Vector2d origin = Eigen::Vector2d::Zero();  ///< the page's bottom-left corner, m
  double tolerance_m = 0.001;  ///< largest distance of a chord from the curve it replaces, m
  /// Element ids and layers (Inkscape layers by label, or any group by id) whose shapes are
  /// obstacles; both empty: every shape.
  std::vector<std::string> ids;
  std::vector<std::string> layers;
};

struct SvgMapResult {
  std::vector<Obstacle> obstacles;
  Eigen::AlignedBox2d page;     ///< the page in the lot, m
  std::vector<bool> ids_found;  ///< per SvgMapDef::ids
  std::vector<bool> layers_found;
  std::size_t parts = 0;  ///< convex parts of the obstacles
};

SvgMapResult readSvgMap(const SvgMapDef& def);

}  // namespace parksim
