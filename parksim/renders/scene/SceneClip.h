#pragma once
// Clipping a Scene's world content to a rectangle of the ground plane. A figure's plot area is
// the data extent its axes frame; obstacles beyond the lot, C-space slices reaching past it and
// footprint outlines at its edge would otherwise run over the axes, tick labels and title. The
// figures clip their content with this before they add the axes (Figures.cpp). Pure: no OpenGL.
//
// Bounds are inclusive, so content lying exactly on the rectangle's edge (the lot's own border,
// a wall face on the lot edge) stays; content within rounding's reach of it (1e-9 of the
// rectangle's larger side) is kept as it is, so a scene with nothing outside comes out
// unchanged. What is cut is cut at the exact border. The test is on x and y; heights are kept.

#include <vector>

#include <Eigen/Core>

#include "parksim/renders/scene/Scene.h"

namespace parksim {

/// The part of a convex polygon (either winding) inside `area` (Sutherland-Hodgman), in the same
/// winding, without repeated consecutive points; the polygon itself when it lies inside. Empty
/// when less than a triangle of positive area is left.
std::vector<Eigen::Vector2d> clipPolygon(const std::vector<Eigen::Vector2d>& polygon,
                                         const Extent2& area);

/// The pieces of `line` inside `area` (Liang-Barsky per segment), as open polylines of the same
/// colour and width; `line` itself (closed or not) when all its points lie inside. A closed line
/// cut by the border gives pieces that together follow its whole inside part, the closing segment
/// included.
std::vector<ScenePolyline> clipPolyline(const ScenePolyline& line, const Extent2& area);

/// Clips everything in `scene` anchored in the world to `area`:
/// - polygons and prisms: their footprint clipped; dropped when nothing is left;
/// - boxes: kept as they are when wholly inside (so a scene with nothing outside is unchanged,
///   and so is its image), dropped when wholly outside, and otherwise replaced by a prism of
///   the clipped footprint with the same heights and colour;
/// - polylines: clipPolyline;
/// - arrows: dropped when the tail lies outside; when the tip does, shortened to end on the
///   border, head scaled with the length (the head's width may still reach up to half of it
///   past the border);
/// - texts anchored at a world point: dropped when the point lies outside (their box is in
///   pixels and may reach past the border); texts fixed on the screen are kept.
/// The extent, focus and background are left alone: the caller frames the result.
void clipToArea(Scene& scene, const Extent2& area);

}  // namespace parksim
