#pragma once
// How an obstacle becomes a Bullet collision shape: one policy for every Bullet world parksim
// builds, the planner's query world (collision/BulletCollisionWorld.h) and the dynamics world
// (sim/world/DynamicsWorld.h). Internal to collision/ and sim/, which keep Bullet a private
// dependency: Bullet's shape type is only declared here, so the header includes no Bullet
// header.
//
// The policy: a box is a btBoxShape, a disc a btCylinderShapeZ, a convex polygon the
// btConvexHullShape of its vertices at the bottom and the top, a compound obstacle a
// btCompoundShape of its parts (rectangles as boxes, other parts as hulls, each by the same
// rules) with a balanced tree of the children's bounds. The shape's frame is at the
// obstacle's box centre (for circles and polygons the centre of their axis-aligned bounding
// rectangle) and half its height, so placed there it stands on the ground, z from 0 to the
// obstacle's height. Whatever the margin, the shape's outer surface, margin included, is the
// obstacle's outline: the margin lies inside it (polygon corners are rounded by its radius).

#include <memory>
#include <vector>

#include <Eigen/Core>

#include "parksim/core/model/Scenario.h"

class btCollisionShape;

namespace parksim {

/// Collision margins of obstacle shapes (Bullet's contact margin, inside the outline).
struct ObstacleShapeDef {
  /// Margin of round and polygonal obstacles, m; at most half a disc's radius and a quarter of
  /// a polygon's smaller bounding half extent. 0: the exact shape.
  double margin_m = 0.0;
  /// Boxes. false: zero margin, and the half extents exactly as given (not (h - m) + m, which
  /// rounds twice). true: Bullet's own margin, a tenth of the smallest half extent and at most
  /// 4 cm, inside the box.
  bool bullet_box_margin = false;
};

/// For worlds whose queries are decided exactly (BulletCollisionWorld: Bullet's box-box
/// detector, and core's separation in double for discs and polygons): no margins.
inline constexpr ObstacleShapeDef kExactObstacleShapes{0.0, false};

/// For worlds whose contacts come from Bullet's GJK and box detectors (DynamicsWorld): 0.5 mm
/// on discs and polygons (Bullet's default 4 cm would round a 5 cm bollard off entirely),
/// Bullet's own margin inside boxes.
inline constexpr ObstacleShapeDef kContactObstacleShapes{0.0005, true};

/// The obstacle's shape as the policy above makes it. The obstacle must be valid (positive
/// sizes; a polygon strictly convex and counter-clockwise): callers check and report first.
std::unique_ptr<btCollisionShape> makeObstacleShape(const Obstacle& obstacle,
                                                    const ObstacleShapeDef& def);

/// A strictly convex counter-clockwise polygon moved inward by `d` on every edge: its vertices,
/// grown by a margin of `d`, give back the polygon (with corners rounded by `d`).
std::vector<Eigen::Vector2d> insetPolygon(const std::vector<Eigen::Vector2d>& polygon, double d);

}  // namespace parksim
