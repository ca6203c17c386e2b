#pragma once
// Configuration-space obstacles of a rectangular robot among box obstacles, exact per heading.
//
// At a fixed heading theta the footprint F(theta) is a rectangle rigidly attached to the
// reference point; it overlaps obstacle O exactly when the reference point lies in
// O (+) (-F(theta)), the Minkowski sum of the obstacle and the footprint reflected through the
// reference point. Both are convex, so the sum is the convex hull of the 16 pairwise corner
// sums: an octagon in general (a rectangle when the two are aligned). The study instead took one
// hull over the corners of all headings, which over-approximates every slice (and fills in
// the non-convex twist between headings); here each heading gets its own slice.

#include <vector>

#include <Eigen/Core>

#include "parksim/core/model/Geometry.h"
#include "parksim/core/model/RobotDef.h"
#include "parksim/core/model/Scenario.h"

namespace parksim {

/// The C-space obstacle slice of `obstacle` at heading `theta_rad`: counter-clockwise convex
/// polygon without repeated or collinear vertices (4 to 8 of them), m.
std::vector<Eigen::Vector2d> cspaceSlice(const OrientedBox& obstacle, const RobotDef& robot,
                                         double theta_rad);

/// The C-space obstacle slice of any obstacle at heading `theta_rad`, counter-clockwise convex
/// polygon, m. Boxes and polygons: exact (the hull of the pairwise vertex sums). Circles: the
/// exact slice is the reflected footprint with its corners rounded by the radius; each quarter
/// arc is drawn with `arc_segments` chords, whose vertices lie on the exact boundary (the
/// chords cut inside it by at most r (1 - cos(pi / (4 arc_segments)))).
std::vector<Eigen::Vector2d> cspaceSlice(const Obstacle& obstacle, const RobotDef& robot,
                                         double theta_rad, int arc_segments = 8);

/// The slices of the obstacle's convex pieces (core's convexPieces) at heading `theta_rad`, as
/// cspaceSlice makes them: one for a box, circle or convex polygon; one per part for a compound
/// obstacle, whose slice is their union (exact: the Minkowski sum distributes over the union).
std::vector<std::vector<Eigen::Vector2d>> cspaceSlices(const Obstacle& obstacle,
                                                       const RobotDef& robot, double theta_rad,
                                                       int arc_segments = 8);

/// Corners of the footprint relative to the reference point, in the robot's frame (x forward),
/// counter-clockwise, m.
std::vector<Eigen::Vector2d> footprintCornersInRobotFrame(const RobotDef& robot);

/// Convex hull, counter-clockwise, collinear points dropped (Andrew's monotone chain).
std::vector<Eigen::Vector2d> convexHull(std::vector<Eigen::Vector2d> points);

/// True when `p` lies strictly inside the counter-clockwise convex polygon, farther than
/// `tolerance_m` from its boundary.
bool insideConvex(const std::vector<Eigen::Vector2d>& polygon, const Eigen::Vector2d& p,
                  double tolerance_m = 0.0);

}  // namespace parksim
