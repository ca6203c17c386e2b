#include "parksim/collision/BulletCollisionWorld.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>

#include <BulletCollision/BroadphaseCollision/btDbvt.h>
#include <BulletCollision/CollisionDispatch/btBoxBoxDetector.h>
#include <BulletCollision/CollisionShapes/btCompoundShape.h>
#include <btBulletCollisionCommon.h>

#include "parksim/collision/ObstacleShape.h"
#include "parksim/core/io/Error.h"
#include "parksim/core/model/Geometry.h"

namespace parksim {

namespace {

// Queries keep no contacts: small pools, not Bullet's default 4,096 contacts, which cost
// ~20 ms of CPU a world to allocate and touch (beyond a pool Bullet takes the heap).
btDefaultCollisionConstructionInfo smallPools() {
  btDefaultCollisionConstructionInfo pools;
  pools.m_defaultMaxPersistentManifoldPoolSize = 64;
  pools.m_defaultMaxCollisionAlgorithmPoolSize = 64;
  return pools;
}

// Broadphase bounds are float and Bullet rounds them; widening the query box by far more than
// a float ulp at lot scale keeps every obstacle that could touch the footprint a candidate.
constexpr double kBroadphasePad_m = 1e-5;

// First search radius of clearance(): about the robot's size, so that a pose near obstacles
// usually needs a single broadphase query.
constexpr double kFirstClearanceRadius_m = 0.05;

bool finite(double v) { return std::isfinite(v); }

btMatrix3x3 yawBasis(double cos_yaw, double sin_yaw) {
  const auto c = static_cast<btScalar>(cos_yaw);
  const auto s = static_cast<btScalar>(sin_yaw);
  return btMatrix3x3(c, -s, 0, s, c, 0, 0, 0, 1);
}

// Records whether the detector reported any point at negative distance. The detector also
// reports touching as distance 0 (or -0), which must stay free.
struct PenetrationResult final : btDiscreteCollisionDetectorInterface::Result {
  bool penetrating = false;
  void setShapeIdentifiersA(int, int) override {}
  void setShapeIdentifiersB(int, int) override {}
  void addContactPoint(const btVector3&, const btVector3&, btScalar distance) override {
    if (distance < 0) penetrating = true;
  }
};

// Collects the obstacle indices of the proxies whose bounds meet the query box. The output
// has capacity for every obstacle, so collecting never allocates.
struct CandidateCollector final : btBroadphaseAabbCallback {
  explicit CandidateCollector(std::vector<int>& out) : out_(out) {}
  bool process(const btBroadphaseProxy* proxy) override {
    const auto* object = static_cast<const btCollisionObject*>(proxy->m_clientObject);
    out_.push_back(object->getUserIndex());
    return true;
  }
  std::vector<int>& out_;
};

// Collects the child indices of a compound shape's tree leaves that meet a box.
struct ChildCollector final : btDbvt::ICollide {
  explicit ChildCollector(std::vector<int>& out) : out_(out) {}
  void Process(const btDbvtNode* leaf) override { out_.push_back(leaf->dataAsInt); }
  std::vector<int>& out_;
};

// Messages start with the scenario's file when it has one, as Error messages do elsewhere.
std::string where(const Scenario& scenario) {
  return (scenario.source_path.empty() ? std::string("collision world") : scenario.source_path) +
         ": ";
}

void requirePositive(const Scenario& scenario, double v, const std::string& what) {
  if (!finite(v) || v <= 0.0) {
    throw Error(where(scenario) + what + " must be positive and finite, got " + std::to_string(v));
  }
}

}  // namespace

struct BulletCollisionWorld::Impl {
  // One obstacle as the queries need it, in double.
  struct Box {
    Obstacle obstacle;  // its shape decides the narrow phase
    OrientedBox box;
    double cos_yaw = 1.0;
    double sin_yaw = 0.0;
    double height_m = 0.0;
  };

  // The query footprint with its heading's cosine and sine, computed once per query.
  struct Footprint : OrientedBox {
    explicit Footprint(const OrientedBox& box)
        : OrientedBox(box), cos_yaw(std::cos(box.yaw)), sin_yaw(std::sin(box.yaw)) {}
    double cos_yaw;
    double sin_yaw;
  };

  RobotDef robot;
  std::vector<std::string> names;
  std::vector<Box> boxes;

  // Members are destroyed in reverse order: the world first (it touches the objects' broadphase
  // proxies when it goes), then the objects, their shapes and the broadphase.
  btDefaultCollisionConfiguration configuration{smallPools()};
  btCollisionDispatcher dispatcher{&configuration};
  btDbvtBroadphase broadphase;
  std::vector<std::unique_ptr<btCollisionShape>> shapes;
  std::vector<std::unique_ptr<btCollisionObject>> objects;
  // Mutable because Bullet's box query is non-const although it changes nothing we rely on.
  mutable btCollisionWorld world{&dispatcher, &broadphase, &configuration};

  // Query scratch: the footprint's size changes with the margin, so one shape is resized per
  // query rather than kept per margin.
  mutable btBoxShape footprint_shape{btVector3(1, 1, 1)};
  mutable std::vector<int> candidates;
  mutable std::vector<int> children;  // scratch: parts of a compound obstacle near the footprint
  mutable Stats stats;

  explicit Impl(const Scenario& scenario) : robot(scenario.robot) {
    requirePositive(scenario, robot.length_m, "robot length");
    requirePositive(scenario, robot.width_m, "robot width");
    requirePositive(scenario, robot.height_m, "robot height");
    if (!finite(robot.front_overhang_m)) {
      throw Error(where(scenario) + "robot front overhang must be finite");
    }

    const std::size_t n = scenario.obstacles.size();
    names.reserve(n);
    boxes.reserve(n);
    shapes.reserve(n);
    objects.reserve(n);
    candidates.reserve(n);
    std::size_t most_parts = 0;
    for (const Obstacle& obstacle : scenario.obstacles) {
      if (obstacle.shape == ObstacleShape::kCompound && obstacle.compound) {
        most_parts = std::max(most_parts, obstacle.compound->parts.size());
      }
    }
    children.reserve(most_parts);
    for (const Obstacle& obstacle : scenario.obstacles) {
      const std::string what = "obstacle '" + obstacle.name + "'";
      requirePositive(scenario, obstacle.box.half_extents.x(), what + " half extent x");
      requirePositive(scenario, obstacle.box.half_extents.y(), what + " half extent y");
      requirePositive(scenario, obstacle.height_m, what + " height");
      if (!obstacle.box.center.allFinite() || !finite(obstacle.box.yaw)) {
        throw Error(where(scenario) + what + " pose must be finite");
      }
      if (obstacle.shape == ObstacleShape::kCircle) {
        requirePositive(scenario, obstacle.radius_m, what + " radius");
      }
      if (obstacle.shape == ObstacleShape::kPolygon && !isStrictlyConvexCcw(obstacle.vertices)) {
        throw Error(where(scenario) + what +
                    " must be a convex polygon with counter-clockwise vertices");
      }
      if (obstacle.shape == ObstacleShape::kCompound &&
          (!obstacle.compound || obstacle.compound->parts.empty())) {
        throw Error(where(scenario) + what + " must have convex parts");
      }
      // Low obstacles pass under the chassis; the planner never meets them (blocksRobot).
      if (!blocksRobot(obstacle, robot)) continue;

      Box box;
      box.obstacle = obstacle;
      box.box = obstacle.box;
      box.cos_yaw = std::cos(obstacle.box.yaw);
      box.sin_yaw = std::sin(obstacle.box.yaw);
      box.height_m = obstacle.height_m;

      // Circles and polygons: Bullet holds their true shape (and its broadphase bounds);
      // penetrates() decides them exactly in double (core's separation), since Bullet's GJK
      // for curved and hull shapes is only accurate to its float tolerances. Boxes: Bullet's
      // box-box detector decides, on exact half extents.
      std::unique_ptr<btCollisionShape> shape = makeObstacleShape(obstacle, kExactObstacleShapes);
      btTransform transform;
      transform.setIdentity();
      if (obstacle.shape == ObstacleShape::kBox) {
        transform.setBasis(yawBasis(box.cos_yaw, box.sin_yaw));
      }
      transform.setOrigin(btVector3(static_cast<btScalar>(obstacle.box.center.x()),
                                    static_cast<btScalar>(obstacle.box.center.y()),
                                    static_cast<btScalar>(0.5 * obstacle.height_m)));

      auto object = std::make_unique<btCollisionObject>();
      object->setWorldTransform(transform);
      object->setCollisionShape(shape.get());
      object->setCollisionFlags(object->getCollisionFlags() | btCollisionObject::CF_STATIC_OBJECT);
      object->setUserIndex(static_cast<int>(boxes.size()));

      names.push_back(obstacle.name);
      boxes.push_back(std::move(box));
      shapes.push_back(std::move(shape));
      objects.push_back(std::move(object));
      // Last, so that an exception above never leaves the world holding an unowned object.
      // Obstacles never test against each other (queries use the broadphase's aabbTest):
      // with the default filter, Bullet would pair every two overlapping obstacles as they
      // are added, and 10,000 obstacles on one spot would take minutes and gigabytes.
      world.addCollisionObject(objects.back().get(), btBroadphaseProxy::StaticFilter,
                               btBroadphaseProxy::AllFilter ^ btBroadphaseProxy::StaticFilter);
    }
    // The scratch shape keeps a zero margin; queries only set its half extents.
    footprint_shape.setMargin(0);
  }

  ~Impl() {
    for (auto& object : objects) world.removeCollisionObject(object.get());
  }

  Impl(const Impl&) = delete;
  Impl& operator=(const Impl&) = delete;

  static void requireFinitePose(const Pose2& pose) {
    if (!finite(pose.x) || !finite(pose.y) || !finite(pose.theta)) {
      throw Error("collision query: pose must be finite");
    }
  }

  static void requireValidMargin(double margin_m) {
    if (!finite(margin_m) || margin_m < 0.0) {
      throw Error("collision query: margin must be finite and >= 0, got " +
                  std::to_string(margin_m));
    }
  }

  // Fills `candidates` with the obstacles whose broadphase bounds meet the footprint's
  // bounds grown by `grow_m`.
  void collectCandidates(const Footprint& footprint, double grow_m) const {
    const double c = std::abs(footprint.cos_yaw);
    const double s = std::abs(footprint.sin_yaw);
    const double pad = grow_m + kBroadphasePad_m;
    const double hx = c * footprint.half_extents.x() + s * footprint.half_extents.y() + pad;
    const double hy = s * footprint.half_extents.x() + c * footprint.half_extents.y() + pad;
    const btVector3 lo(static_cast<btScalar>(footprint.center.x() - hx),
                       static_cast<btScalar>(footprint.center.y() - hy),
                       static_cast<btScalar>(-pad));
    const btVector3 hi(static_cast<btScalar>(footprint.center.x() + hx),
                       static_cast<btScalar>(footprint.center.y() + hy),
                       static_cast<btScalar>(robot.height_m + pad));
    candidates.clear();
    CandidateCollector collector(candidates);
    // btCollisionWorld offers no box query of its own; its broadphase does.
    world.getBroadphase()->aabbTest(lo, hi, collector);
  }

  // Sizes the scratch footprint shape; once per query, before penetrates().
  void prepareFootprint(const Footprint& footprint) const {
    footprint_shape.setImplicitShapeDimensions(
        btVector3(static_cast<btScalar>(footprint.half_extents.x()),
                  static_cast<btScalar>(footprint.half_extents.y()),
                  static_cast<btScalar>(0.5 * robot.height_m)));
  }

  // Fills `children` with the parts of compound obstacle i whose bounds meet the footprint's
  // bounds grown by `grow_m`, from the compound shape's tree (in its frame: the obstacle's
  // bounding-rectangle centre).
  void collectChildren(int i, const Footprint& footprint, double grow_m) const {
    const std::size_t k = static_cast<std::size_t>(i);
    const auto* compound = static_cast<const btCompoundShape*>(shapes[k].get());
    const Eigen::Vector2d c = footprint.center - boxes[k].box.center;
    const double hx = std::abs(footprint.cos_yaw) * footprint.half_extents.x() +
                      std::abs(footprint.sin_yaw) * footprint.half_extents.y() + grow_m +
                      kBroadphasePad_m;
    const double hy = std::abs(footprint.sin_yaw) * footprint.half_extents.x() +
                      std::abs(footprint.cos_yaw) * footprint.half_extents.y() + grow_m +
                      kBroadphasePad_m;
    const btVector3 lo(btScalar(c.x() - hx), btScalar(c.y() - hy), btScalar(-boxes[k].height_m));
    const btVector3 hi(btScalar(c.x() + hx), btScalar(c.y() + hy), btScalar(boxes[k].height_m));
    children.clear();
    ChildCollector collector(children);
    compound->getDynamicAabbTree()->collideTV(compound->getDynamicAabbTree()->m_root,
                                              btDbvtVolume::FromMM(lo, hi), collector);
  }

  // A compound obstacle: exact tests in double against the parts its tree finds near.
  bool compoundPenetrates(int i, const Footprint& footprint) const {
    collectChildren(i, footprint, 0.0);
    const CompoundShape& shape = *boxes[static_cast<std::size_t>(i)].obstacle.compound;
    return std::any_of(children.begin(), children.end(), [&](int c) {
      ++stats.shape_tests;
      return separationAlongAxes(footprint, shape.parts[static_cast<std::size_t>(c)]) < 0.0;
    });
  }

  // Distance to obstacle i, exact; for a compound obstacle over the parts within `radius_m`
  // (infinity when none is).
  double distanceTo(int i, const Footprint& footprint, double radius_m) const {
    const Obstacle& obstacle = boxes[static_cast<std::size_t>(i)].obstacle;
    if (obstacle.shape != ObstacleShape::kCompound) return distance(footprint, obstacle);
    collectChildren(i, footprint, radius_m);
    double best = std::numeric_limits<double>::infinity();
    for (int c : children) {
      best = std::min(best,
                      distance(footprint, obstacle.compound->parts[static_cast<std::size_t>(c)]));
    }
    return best;
  }

  // Box-box test of the prepared footprint against obstacle i. The footprint is expressed in
  // the obstacle's frame (computed in double) so that Bullet's float arithmetic works on
  // offsets of a few decimetres instead of lot coordinates. Measured on the lot: answers stay
  // right down to 1e-7 m from touching (first errors at 3e-8 m), where world coordinates
  // misclassify 0.14% of near-contact poses at 1e-7 m.
  bool penetrates(int i, const Footprint& footprint) const {
    const Box& obstacle = boxes[static_cast<std::size_t>(i)];
    if (obstacle.obstacle.shape == ObstacleShape::kCompound) {
      return compoundPenetrates(i, footprint);
    }
    if (obstacle.obstacle.shape != ObstacleShape::kBox) {
      ++stats.shape_tests;
      return separation(footprint, obstacle.obstacle) < 0.0;
    }
    ++stats.box_box_tests;
    const Eigen::Vector2d d = footprint.center - obstacle.box.center;
    const double rel_x = obstacle.cos_yaw * d.x() + obstacle.sin_yaw * d.y();
    const double rel_y = -obstacle.sin_yaw * d.x() + obstacle.cos_yaw * d.y();
    // cos and sin of (footprint yaw - obstacle yaw), without calling trigonometry per pair.
    const double rel_cos =
        footprint.cos_yaw * obstacle.cos_yaw + footprint.sin_yaw * obstacle.sin_yaw;
    const double rel_sin =
        footprint.sin_yaw * obstacle.cos_yaw - footprint.cos_yaw * obstacle.sin_yaw;

    btDiscreteCollisionDetectorInterface::ClosestPointInput input;
    input.m_transformA.setIdentity();
    input.m_transformB.setBasis(yawBasis(rel_cos, rel_sin));
    input.m_transformB.setOrigin(
        btVector3(static_cast<btScalar>(rel_x), static_cast<btScalar>(rel_y),
                  static_cast<btScalar>(0.5 * (robot.height_m - obstacle.height_m))));
    btBoxBoxDetector detector(static_cast<btBoxShape*>(shapes[static_cast<std::size_t>(i)].get()),
                              &footprint_shape);
    PenetrationResult result;
    detector.getClosestPoints(input, result, nullptr);
    return result.penetrating;
  }
};

BulletCollisionWorld::BulletCollisionWorld(const Scenario& scenario)
    : impl_(std::make_unique<Impl>(scenario)) {}

BulletCollisionWorld::~BulletCollisionWorld() = default;
BulletCollisionWorld::BulletCollisionWorld(BulletCollisionWorld&&) noexcept = default;
BulletCollisionWorld& BulletCollisionWorld::operator=(BulletCollisionWorld&&) noexcept = default;

bool BulletCollisionWorld::isFree(const Pose2& pose, double margin_m) const {
  Impl& m = *impl_;
  ++m.stats.free_queries;
  Impl::requireFinitePose(pose);
  Impl::requireValidMargin(margin_m);
  const Impl::Footprint footprint(footprintAt(m.robot, pose, margin_m));
  m.collectCandidates(footprint, 0.0);
  if (m.candidates.empty()) return true;
  m.prepareFootprint(footprint);
  return std::none_of(m.candidates.begin(), m.candidates.end(),
                      [&](int i) { return m.penetrates(i, footprint); });
}

std::vector<std::string> BulletCollisionWorld::overlapping(const Pose2& pose,
                                                           double margin_m) const {
  Impl& m = *impl_;
  ++m.stats.overlapping_queries;
  Impl::requireFinitePose(pose);
  Impl::requireValidMargin(margin_m);
  const Impl::Footprint footprint(footprintAt(m.robot, pose, margin_m));
  m.collectCandidates(footprint, 0.0);
  m.prepareFootprint(footprint);
  std::sort(m.candidates.begin(), m.candidates.end());
  std::vector<std::string> names;
  for (int i : m.candidates) {
    if (m.penetrates(i, footprint)) names.push_back(m.names[static_cast<std::size_t>(i)]);
  }
  return names;
}

double BulletCollisionWorld::clearance(const Pose2& pose) const {
  Impl& m = *impl_;
  ++m.stats.clearance_queries;
  Impl::requireFinitePose(pose);
  if (m.boxes.empty()) return std::numeric_limits<double>::infinity();
  const Impl::Footprint footprint(footprintAt(m.robot, pose, 0.0));
  // An obstacle within distance r of the footprint has bounds meeting the footprint's bounds
  // grown by r, so the nearest candidate is the nearest obstacle once its distance is <= r.
  double radius = kFirstClearanceRadius_m;
  for (;;) {
    m.collectCandidates(footprint, radius);
    double best = std::numeric_limits<double>::infinity();
    for (int i : m.candidates) {
      best = std::min(best, m.distanceTo(i, footprint, radius));
      if (best == 0.0) return 0.0;
    }
    if (best <= radius) return best;
    // Either nothing within reach yet (grow geometrically), or a candidate at distance best
    // whose bounds-based search may have missed a nearer obstacle outside the box corners.
    radius = std::isfinite(best) ? best : 4.0 * radius;
  }
}

std::size_t BulletCollisionWorld::obstacleCount() const { return impl_->boxes.size(); }

BulletCollisionWorld::Stats BulletCollisionWorld::stats() const { return impl_->stats; }

void BulletCollisionWorld::resetStats() { impl_->stats = Stats{}; }

}  // namespace parksim
