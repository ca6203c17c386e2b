#include "parksim/collision/ObstacleShape.h"

#include <algorithm>

#include <BulletCollision/CollisionShapes/btBoxShape.h>
#include <BulletCollision/CollisionShapes/btConvexHullShape.h>
#include <BulletCollision/CollisionShapes/btCylinderShape.h>

namespace parksim {

namespace {

std::unique_ptr<btCollisionShape> boxShape(const Obstacle& o, const ObstacleShapeDef& def) {
  const btVector3 half(btScalar(o.box.half_extents.x()), btScalar(o.box.half_extents.y()),
                       btScalar(0.5 * o.height_m));
  // The constructor keeps the outer size and puts Bullet's margin inside.
  auto shape = std::make_unique<btBoxShape>(half);
  if (!def.bullet_box_margin) {
    // Zero margin, and the half extents bit for bit instead of (h - m) + m.
    shape->setMargin(0);
    shape->setImplicitShapeDimensions(half);
  }
  return shape;
}

std::unique_ptr<btCollisionShape> discShape(const Obstacle& o, const ObstacleShapeDef& def) {
  const auto r = btScalar(o.radius_m);
  auto shape = std::make_unique<btCylinderShapeZ>(btVector3(r, r, btScalar(0.5 * o.height_m)));
  // btCylinderShape keeps its outer size when the margin changes.
  shape->setMargin(btScalar(std::min(def.margin_m, 0.5 * o.radius_m)));
  return shape;
}

std::unique_ptr<btCollisionShape> polygonShape(const Obstacle& o, const ObstacleShapeDef& def) {
  const double hz = 0.5 * o.height_m;
  const double margin =
      std::min(def.margin_m, 0.25 * std::min(o.box.half_extents.x(), o.box.half_extents.y()));
  auto shape = std::make_unique<btConvexHullShape>();
  const std::vector<Eigen::Vector2d> core =
      margin > 0.0 ? insetPolygon(o.vertices, margin) : o.vertices;
  for (const Eigen::Vector2d& v : core) {
    const Eigen::Vector2d d = v - o.box.center;
    for (const double z : {-(hz - margin), hz - margin}) {
      shape->addPoint(btVector3(btScalar(d.x()), btScalar(d.y()), btScalar(z)), false);
    }
  }
  // The cached bounding box takes in the margin set when it is computed (Bullet's default,
  // 4 cm, here), and Bullet adds the current margin again when it reports the box: the
  // broadphase sees the polygon 4 cm larger than it is. Harmless to the answers (every query
  // and contact is decided on the shape itself), but setting the margin first changes when
  // contact manifolds are created in the dynamics world, and with it the float rounding of
  // the episode on worlds/bollards.yaml; kept as it was.
  shape->recalcLocalAabb();
  shape->setMargin(btScalar(margin));
  return shape;
}

}  // namespace

std::unique_ptr<btCollisionShape> makeObstacleShape(const Obstacle& obstacle,
                                                    const ObstacleShapeDef& def) {
  switch (obstacle.shape) {
    case ObstacleShape::kBox: break;
    case ObstacleShape::kCircle: return discShape(obstacle, def);
    case ObstacleShape::kPolygon: return polygonShape(obstacle, def);
  }
  return boxShape(obstacle, def);
}

std::vector<Eigen::Vector2d> insetPolygon(const std::vector<Eigen::Vector2d>& polygon, double d) {
  const std::size_t n = polygon.size();
  auto outward = [&](std::size_t i) {
    const Eigen::Vector2d e = (polygon[(i + 1) % n] - polygon[i]).normalized();
    return Eigen::Vector2d(e.y(), -e.x());
  };
  std::vector<Eigen::Vector2d> out(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::Vector2d n0 = outward((i + n - 1) % n);
    const Eigen::Vector2d n1 = outward(i);
    out[i] = polygon[i] - d * (n0 + n1) / (1.0 + n0.dot(n1));
  }
  return out;
}

}  // namespace parksim
