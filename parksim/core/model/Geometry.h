#pragma once
// Planar oriented boxes and an exact separating-axis overlap test. Used as the independent
// reference for the Bullet collision adapter, and by rendering and C-space figures.

#include <array>
#include <vector>

#include <Eigen/Core>

#include "parksim/core/geometry/Pose2.h"
#include "parksim/core/model/RobotDef.h"

namespace parksim {

/// A rectangle in the plane.
struct OrientedBox {
  Eigen::Vector2d center = Eigen::Vector2d::Zero();        ///< m
  Eigen::Vector2d half_extents = Eigen::Vector2d::Zero();  ///< m, along the box's own x and y
  double yaw = 0.0;                                        ///< rad

  /// Corners counter-clockwise, starting at (+x, -y) in the box frame.
  std::array<Eigen::Vector2d, 4> corners() const;

  friend bool operator==(const OrientedBox&, const OrientedBox&) = default;
};

/// A disc in the plane: round bollards and pillars.
struct Circle {
  Eigen::Vector2d center = Eigen::Vector2d::Zero();  ///< m
  double radius = 0.0;                               ///< m
};

/// Exact overlap test by separating axes. Boxes that only touch (zero-area intersection)
/// do not overlap.
bool boxesOverlap(const OrientedBox& a, const OrientedBox& b);

/// Signed distance between two boxes along the best separating axis, m: positive when
/// separated (a lower bound of the true gap), negative when overlapping (minus the
/// penetration depth along the axis of least overlap).
double separationAlongAxes(const OrientedBox& a, const OrientedBox& b);

/// A box's unit axes, its own x and y: (cos yaw, sin yaw) and (-sin yaw, cos yaw).
struct BoxAxes {
  Eigen::Vector2d x;
  Eigen::Vector2d y;
};
BoxAxes axesOf(double yaw);
BoxAxes axesOf(const OrientedBox& b);

/// separationAlongAxes(a, b) with both boxes' axes given (`own_a` = axesOf(a), `own_b` =
/// axesOf(b)), the same to the last bit: for callers that test one box against many, or many
/// against one, without their sines and cosines each time (the search heuristic's grid).
double separationAlongAxes(const OrientedBox& a, const BoxAxes& own_a, const OrientedBox& b,
                           const BoxAxes& own_b);

/// Signed separation of a box and a disc, exact: the distance from the box to the disc's
/// centre minus the radius (positive when apart, negative when overlapping, 0 when touching).
double separation(const OrientedBox& a, const Circle& c);

/// Signed separation of a box and a convex polygon (counter-clockwise vertices) along the best
/// separating axis among both shapes' edge normals, m: positive when separated (a lower bound
/// of the true gap), negative when overlapping (minus the penetration along the axis of least
/// overlap), 0 when touching.
double separationAlongAxes(const OrientedBox& a, const std::vector<Eigen::Vector2d>& polygon);
/// The same with the box's axes given (`own` = axesOf(a)), to the last bit.
double separationAlongAxes(const OrientedBox& a, const BoxAxes& own,
                           const std::vector<Eigen::Vector2d>& polygon);

/// Exact planar distance between a box and a convex polygon, m (0 when touching or overlapping).
double distance(const OrientedBox& a, const std::vector<Eigen::Vector2d>& polygon);

/// Exact planar distance between two boxes, m (0 when touching or overlapping).
double distance(const OrientedBox& a, const OrientedBox& b);

/// Twice the signed area of a polygon: positive for counter-clockwise vertices.
double signedDoubleArea(const std::vector<Eigen::Vector2d>& polygon);

/// True when the polygon has at least 3 vertices, winds counter-clockwise, and every turn is
/// strictly left (convex, no repeated or collinear vertices).
bool isStrictlyConvexCcw(const std::vector<Eigen::Vector2d>& polygon);

/// The robot's footprint rectangle at `pose`, grown by `margin_m` on every side.
OrientedBox footprintAt(const RobotDef& robot, const Pose2& pose, double margin_m = 0.0);

/// Largest distance from the reference point to any footprint corner, m.
double footprintRadius(const RobotDef& robot);

}  // namespace parksim
