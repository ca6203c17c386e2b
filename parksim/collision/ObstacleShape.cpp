#include "parksim/collision/ObstacleShape.h"

#include <algorithm>
#include <cmath>

#include <BulletCollision/BroadphaseCollision/btDbvt.h>
#include <BulletCollision/CollisionShapes/btBoxShape.h>
#include <BulletCollision/CollisionShapes/btCompoundShape.h>
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

// btCompoundShape does not own its children; this one does.
class OwningCompoundShape final : public btCompoundShape {
 public:
  OwningCompoundShape() : btCompoundShape(false) {}
  void add(const btTransform& local, std::unique_ptr<btCollisionShape> child) {
    addChildShape(local, child.get());
    children_.push_back(std::move(child));
  }

 private:
  std::vector<std::unique_ptr<btCollisionShape>> children_;
};

// A rectangle among a compound's parts (a map's merged cells): its centre, half extents and
// heading, when its four corners make one to within rounding of the map's rotation.
bool asRectangle(const std::vector<Eigen::Vector2d>& part, OrientedBox& box) {
  if (part.size() != 4) return false;
  const Eigen::Vector2d e0 = part[1] - part[0];
  const Eigen::Vector2d e1 = part[2] - part[1];
  const Eigen::Vector2d e2 = part[3] - part[2];
  const Eigen::Vector2d e3 = part[0] - part[3];
  const double scale = e0.norm() * e1.norm();
  if (!(scale > 0.0) || std::abs(e0.dot(e1)) > 1e-9 * scale ||
      (e0 + e2).norm() > 1e-9 * e0.norm() || (e1 + e3).norm() > 1e-9 * e1.norm()) {
    return false;
  }
  box.center = 0.25 * (part[0] + part[1] + part[2] + part[3]);
  box.half_extents = {0.5 * e0.norm(), 0.5 * e1.norm()};
  box.yaw = std::atan2(e0.y(), e0.x());
  return true;
}

// Each part a child at its place relative to the obstacle's bounding-rectangle centre: boxes for
// rectangles, hulls otherwise, with the margins of the policy. The children's bounding-volume
// tree is built balanced once all are in (a map's thousands of rectangles).
std::unique_ptr<btCollisionShape> compoundShape(const Obstacle& o, const ObstacleShapeDef& def) {
  auto shape = std::make_unique<OwningCompoundShape>();
  for (const std::vector<Eigen::Vector2d>& part : o.compound->parts) {
    OrientedBox rect;
    btTransform local;
    local.setIdentity();
    if (asRectangle(part, rect)) {
      Obstacle piece = Obstacle::makeBox("", o.kind, rect, o.height_m);
      const Eigen::Vector2d d = rect.center - o.box.center;
      local.setOrigin(btVector3(btScalar(d.x()), btScalar(d.y()), 0));
      local.setRotation(btQuaternion(btVector3(0, 0, 1), btScalar(rect.yaw)));
      shape->add(local, boxShape(piece, def));
      continue;
    }
    Obstacle piece = Obstacle::makePolygon("", o.kind, part, o.height_m);
    const Eigen::Vector2d d = piece.box.center - o.box.center;
    local.setOrigin(btVector3(btScalar(d.x()), btScalar(d.y()), 0));
    shape->add(local, polygonShape(piece, def));
  }
  shape->createAabbTreeFromChildren();
  shape->getDynamicAabbTree()->optimizeTopDown();
  return shape;
}

}  // namespace

std::unique_ptr<btCollisionShape> makeObstacleShape(const Obstacle& obstacle,
                                                    const ObstacleShapeDef& def) {
  switch (obstacle.shape) {
    case ObstacleShape::kBox: break;
    case ObstacleShape::kCircle: return discShape(obstacle, def);
    case ObstacleShape::kPolygon: return polygonShape(obstacle, def);
    case ObstacleShape::kCompound: return compoundShape(obstacle, def);
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
