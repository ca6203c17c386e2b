#include "parksim/sim/DynamicsWorld.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <unordered_map>
#include <vector>

#include <BulletCollision/BroadphaseCollision/btDbvtBroadphase.h>
#include <BulletCollision/CollisionDispatch/btCollisionDispatcher.h>
#include <BulletCollision/CollisionDispatch/btDefaultCollisionConfiguration.h>
#include <BulletCollision/CollisionShapes/btBoxShape.h>
#include <BulletCollision/CollisionShapes/btConvexHullShape.h>
#include <BulletCollision/CollisionShapes/btCylinderShape.h>
#include <BulletCollision/CollisionShapes/btSphereShape.h>
#include <BulletDynamics/Dynamics/btRigidBody.h>
#include <BulletDynamics/Featherstone/btMultiBody.h>
#include <BulletDynamics/Featherstone/btMultiBodyConstraintSolver.h>
#include <BulletDynamics/Featherstone/btMultiBodyDynamicsWorld.h>
#include <BulletDynamics/Featherstone/btMultiBodyJointMotor.h>
#include <BulletDynamics/Featherstone/btMultiBodyLinkCollider.h>

#include "parksim/core/Error.h"
#include "parksim/core/Geometry.h"
#include "parksim/core/ProvenanceConfig.h"
#include "parksim/sim/FastMultiBodySolver.h"

namespace parksim {

// Result files record Bullet's precision (parksim/core/Provenance.h); it must be the one compiled.
static_assert(sizeof(btScalar) == (PARKSIM_BULLET_DOUBLE ? sizeof(double) : sizeof(float)),
              "cmake/Provenance.cmake and Bullet's headers disagree on BT_USE_DOUBLE_PRECISION");

namespace {

// Collision filter groups. Wheels and slider touch only the ground and the chassis only
// obstacles: the 20 mm wheels reach 10 mm past the front edge, and letting them hit obstacles
// would make the robot's contact shape larger than the footprint the planner checks.
enum Group : int {
  kGroundGroup = 1 << 0,
  kStaticGroup = 1 << 1,
  kParkedGroup = 1 << 2,
  kChassisGroup = 1 << 3,
  kWheelGroup = 1 << 4,
};
constexpr int kGroundMask = kWheelGroup | kParkedGroup;
constexpr int kStaticMask = kChassisGroup | kParkedGroup;
constexpr int kParkedMask = kGroundGroup | kStaticGroup | kParkedGroup | kChassisGroup;
constexpr int kChassisMask = kStaticGroup | kParkedGroup;
constexpr int kWheelMask = kGroundGroup;

// User index of collision objects that are not obstacles (obstacles carry their index).
constexpr int kNotObstacle = -1;

// The groups and masks above, and no pair of two fixed obstacles (walls, parked robots not yet
// woken): they cannot move, so a pair of them is pure cost, and parked robots may overlap each
// other (docs/world-format.md): with the masks alone, Bullet would keep and visit every step a
// pair for every two of n overlapping parked robots, n^2 / 2 of them (10,000 on one spot ran
// out of memory). A woken parked robot is re-added and pairs with its neighbours as before.
struct FixedObstaclePairFilter final : btOverlapFilterCallback {
  bool needBroadphaseCollision(btBroadphaseProxy* a, btBroadphaseProxy* b) const override {
    if ((a->m_collisionFilterGroup & b->m_collisionFilterMask) == 0 ||
        (b->m_collisionFilterGroup & a->m_collisionFilterMask) == 0) {
      return false;
    }
    const auto* oa = static_cast<const btCollisionObject*>(a->m_clientObject);
    const auto* ob = static_cast<const btCollisionObject*>(b->m_clientObject);
    const auto fixed_obstacle = [](const btCollisionObject* o) {
      return o->isStaticObject() && o->getUserIndex() != kNotObstacle;
    };
    return !(fixed_obstacle(oa) && fixed_obstacle(ob));
  }
};

constexpr int kLeftWheel = 0;
constexpr int kRightWheel = 1;
constexpr int kSupport = 2;

void requirePositive(double value, const char* what) {
  if (!(value > 0.0) || !std::isfinite(value)) {
    throw Error(std::string("simulation: ") + what + " must be positive, got " +
                std::to_string(value));
  }
}

btTransform planarTransform(double x, double y, double z, double yaw) {
  btTransform tr;
  tr.setIdentity();
  tr.setOrigin(btVector3(btScalar(x), btScalar(y), btScalar(z)));
  tr.setRotation(btQuaternion(btVector3(0, 0, 1), btScalar(yaw)));
  return tr;
}

// Collision margin of round and polygonal obstacles, m. Bullet's default (4 cm) would round a
// 5 cm bollard off entirely; the shapes are built so that their outer surface, margin
// included, is the obstacle's exact outline (polygon corners rounded by this radius).
constexpr double kShapeMargin_m = 0.0005;

// A convex counter-clockwise polygon moved inward by `d` on every edge: its vertices, grown
// by a margin of `d`, give back the polygon (with rounded corners).
std::vector<Eigen::Vector2d> insetPolygon(const std::vector<Eigen::Vector2d>& poly, double d) {
  const std::size_t n = poly.size();
  auto outward = [&](std::size_t i) {
    const Eigen::Vector2d e = (poly[(i + 1) % n] - poly[i]).normalized();
    return Eigen::Vector2d(e.y(), -e.x());
  };
  std::vector<Eigen::Vector2d> out(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::Vector2d n0 = outward((i + n - 1) % n);
    const Eigen::Vector2d n1 = outward(i);
    out[i] = poly[i] - d * (n0 + n1) / (1.0 + n0.dot(n1));
  }
  return out;
}

double yawOf(const btTransform& tr) {
  const btMatrix3x3& r = tr.getBasis();
  return std::atan2(double(r[1][0]), double(r[0][0]));
}

}  // namespace

struct DynamicsWorld::Impl {
  RobotDef robot;
  PhysicsDef physics;
  SimModelDef model;
  std::vector<Obstacle> obstacles;
  LotBounds lot;
  // Origin of Bullet's local frame in the lot frame, m (SimModelDef::local_frame_grid_m).
  double ox = 0.0;
  double oy = 0.0;
  // True geometry (TrueRobotDef applied to the nominal robot), m.
  double left_radius = 0.0;
  double right_radius = 0.0;
  double true_track = 0.0;

  std::unique_ptr<btDefaultCollisionConfiguration> config;
  std::unique_ptr<btCollisionDispatcher> dispatcher;
  FixedObstaclePairFilter pair_filter;  // outlives the broadphase that points to it
  std::unique_ptr<btDbvtBroadphase> broadphase;
  std::unique_ptr<btMultiBodyConstraintSolver> solver;
  std::unique_ptr<btMultiBodyDynamicsWorld> world;

  std::vector<std::unique_ptr<btCollisionShape>> shapes;
  std::vector<std::unique_ptr<btRigidBody>> bodies;  // ground first, then obstacles in order
  std::unique_ptr<btMultiBody> ego;
  std::vector<std::unique_ptr<btMultiBodyLinkCollider>> colliders;  // chassis, wheels, support
  std::vector<std::unique_ptr<btMultiBodyJointMotor>> motors;       // left, right

  // Chassis centre relative to the reference point, in the chassis frame, m.
  double chassis_dx = 0.0;
  double chassis_z = 0.0;

  WheelSpeeds targets;
  WheelSpeeds torques;
  RobotState state;
  long step_count = 0;
  std::vector<int> contacts;
  std::vector<int> candidates;  // scratch of wakeNearbyParkedRobots
  std::vector<int> woken;       // parked robots with mass, in the order they were woken

  ~Impl() {
    if (!world) return;
    for (auto& motor : motors) world->removeMultiBodyConstraint(motor.get());
    for (auto& collider : colliders) world->removeCollisionObject(collider.get());
    if (ego) world->removeMultiBody(ego.get());
    for (auto& body : bodies) {
      if (body) world->removeRigidBody(body.get());
    }
  }

  btBoxShape* box(double hx, double hy, double hz) {
    auto shape = std::make_unique<btBoxShape>(btVector3(btScalar(hx), btScalar(hy), btScalar(hz)));
    btBoxShape* raw = shape.get();
    shapes.push_back(std::move(shape));
    return raw;
  }

  btSphereShape* sphere(double r) {
    auto shape = std::make_unique<btSphereShape>(btScalar(r));
    btSphereShape* raw = shape.get();
    shapes.push_back(std::move(shape));
    return raw;
  }

  // Every body starts fixed (mass 0); parked robots get their mass in wake().
  btRigidBody* addFixedBody(btCollisionShape* shape, const btTransform& tr, double friction,
                            int group, int mask, int user_index) {
    btRigidBody::btRigidBodyConstructionInfo info(0, nullptr, shape, btVector3(0, 0, 0));
    info.m_startWorldTransform = tr;
    info.m_friction = btScalar(friction);
    info.m_linearDamping = 0;
    info.m_angularDamping = 0;
    auto body = std::make_unique<btRigidBody>(info);
    body->setUserIndex(user_index);
    btRigidBody* raw = body.get();
    world->addRigidBody(raw, group, mask);
    world->updateSingleAabb(raw);
    bodies.push_back(std::move(body));
    return raw;
  }

  // The fixed box of obstacle i, as buildWorld places it.
  btTransform obstacleTransform(std::size_t i) const {
    const Obstacle& o = obstacles[i];
    return planarTransform(o.box.center.x() - ox, o.box.center.y() - oy, 0.5 * o.height_m,
                           o.box.yaw);
  }

  // Where obstacle i is: its body's transform, or for a parked robot not inserted yet the
  // transform it will get (the same floats).
  btTransform obstacleWorldTransform(std::size_t i) const {
    const btRigidBody* body = bodies[i + 1].get();
    return body != nullptr ? body->getWorldTransform() : obstacleTransform(i);
  }

  // Lazy parked robots (SimModelDef::parked_lazy_count): a grid of cells of
  // parked_insert_distance_m, each listing the robots whose box touches it.
  bool lazy = false;
  double cell = 1.0;
  std::unordered_map<std::int64_t, std::vector<int>> grid;
  bool queried = false;
  Eigen::Vector2d last_query{0.0, 0.0};

  static std::int64_t cellKey(std::int64_t cx, std::int64_t cy) {
    return (cx << 32) ^ (cy & 0xffffffffLL);
  }

  void buildGrid() {
    for (std::size_t i = 0; i < obstacles.size(); ++i) {
      if (obstacles[i].kind != ObstacleKind::kParkedRobot) continue;
      const OrientedBox& b = obstacles[i].box;
      const double r = b.half_extents.norm();
      const auto lo_x = static_cast<std::int64_t>(std::floor((b.center.x() - r) / cell));
      const auto hi_x = static_cast<std::int64_t>(std::floor((b.center.x() + r) / cell));
      const auto lo_y = static_cast<std::int64_t>(std::floor((b.center.y() - r) / cell));
      const auto hi_y = static_cast<std::int64_t>(std::floor((b.center.y() + r) / cell));
      for (std::int64_t cx = lo_x; cx <= hi_x; ++cx) {
        for (std::int64_t cy = lo_y; cy <= hi_y; ++cy) {
          grid[cellKey(cx, cy)].push_back(static_cast<int>(i));
        }
      }
    }
  }

  // Inserts every parked robot within ~parked_insert_distance_m of the robot. Re-queried only
  // after the robot moved a quarter of that distance, so a step costs O(1) however many
  // parked robots the world has.
  void insertNearbyParkedRobots(const Pose2& ego_pose) {
    const Eigen::Vector2d p(ego_pose.x, ego_pose.y);
    if (queried && (p - last_query).norm() < 0.25 * cell) return;
    queried = true;
    last_query = p;
    const double reach = cell + robot.length_m + robot.width_m;
    std::vector<int> found;
    const auto lo_x = static_cast<std::int64_t>(std::floor((p.x() - reach) / cell));
    const auto hi_x = static_cast<std::int64_t>(std::floor((p.x() + reach) / cell));
    const auto lo_y = static_cast<std::int64_t>(std::floor((p.y() - reach) / cell));
    const auto hi_y = static_cast<std::int64_t>(std::floor((p.y() + reach) / cell));
    for (std::int64_t cx = lo_x; cx <= hi_x; ++cx) {
      for (std::int64_t cy = lo_y; cy <= hi_y; ++cy) {
        const auto it = grid.find(cellKey(cx, cy));
        if (it == grid.end()) continue;
        for (int i : it->second) {
          if (!bodies[static_cast<std::size_t>(i) + 1]) found.push_back(i);
        }
      }
    }
    std::sort(found.begin(), found.end());
    found.erase(std::unique(found.begin(), found.end()), found.end());
    for (int i : found) insertObstacle(static_cast<std::size_t>(i));
  }

  void insertObstacle(std::size_t i) {
    const Obstacle& o = obstacles[i];
    btCollisionShape* shape = obstacleShape(o);
    const bool parked = o.kind == ObstacleKind::kParkedRobot;
    // Obstacles no higher than the ground clearance pass under the chassis (blocksRobot);
    // they are in the world to be seen, and collide with nothing.
    const bool blocks = blocksRobot(o, robot);
    addFixedBody(shape, obstacleTransform(i), physics.obstacle_friction,
                 parked ? kParkedGroup : kStaticGroup,
                 !blocks  ? 0
                 : parked ? kParkedMask
                          : kStaticMask,
                 static_cast<int>(i));
    // addFixedBody appended it; it belongs in obstacle i's slot.
    bodies[i + 1] = std::move(bodies.back());
    bodies.pop_back();
  }

  void buildWorld() {
    config = std::make_unique<btDefaultCollisionConfiguration>();
    dispatcher = std::make_unique<btCollisionDispatcher>(config.get());
    broadphase = std::make_unique<btDbvtBroadphase>();
    broadphase->getOverlappingPairCache()->setOverlapFilterCallback(&pair_filter);
    solver = model.solver == SolverKernel::kBullet
                 ? std::make_unique<btMultiBodyConstraintSolver>()
                 : makeFastMultiBodySolver(model.solver == SolverKernel::kFast);
    world = std::make_unique<btMultiBodyDynamicsWorld>(dispatcher.get(), broadphase.get(),
                                                       solver.get(), config.get());
    world->setGravity(btVector3(0, 0, btScalar(-physics.gravity_mps2)));
    world->getSolverInfo().m_numIterations = physics.solver_iterations;
    world->getSolverInfo().m_leastSquaresResidualThreshold =
        btScalar(model.solver_residual_threshold);
    // Bullet recomputes every object's bounding box every step by default, fixed ones
    // included. Fixed boxes get theirs once, below (updateSingleAabb adds the contact
    // threshold exactly as the per-step update did); moving bodies are still updated.
    world->setForceUpdateAllAabbs(false);

    // The ground is a slab, not a btStaticPlaneShape: plane contacts are made by perturbing the
    // box, which nudged every resting parked robot by 0.03 mm on its first awake step; the
    // box-box detector gives exact corner contacts. Sized to the lot plus a metre, not larger,
    // so that float rounding in the detector stays near 1e-7 m.
    // For a large lot only the region the robot drives in (plus a margin) gets ground: the
    // detector's rounding grows with the slab's size (a 200 m slab rounds by ~1e-5 m).
    const double ground_half_thickness = 0.05;
    double half_x = 0.5 * (lot.x_max_m - lot.x_min_m) + 1.0;
    double half_y = 0.5 * (lot.y_max_m - lot.y_min_m) + 1.0;
    double cx = 0.5 * (lot.x_min_m + lot.x_max_m);
    double cy = 0.5 * (lot.y_min_m + lot.y_max_m);
    if (model.has_reach) {
      const double g = model.ground_margin_m;
      const auto clip = [](double lo, double hi, double reach_lo, double reach_hi, double& half,
                           double& centre) {
        if (reach_lo <= lo && reach_hi >= hi) return;  // the whole lot: as always
        lo = std::max(lo, reach_lo);
        hi = std::min(hi, reach_hi);
        half = 0.5 * (hi - lo);
        centre = 0.5 * (lo + hi);
      };
      clip(lot.x_min_m - 1.0, lot.x_max_m + 1.0, model.reach.x_min_m - g, model.reach.x_max_m + g,
           half_x, cx);
      clip(lot.y_min_m - 1.0, lot.y_max_m + 1.0, model.reach.y_min_m - g, model.reach.y_max_m + g,
           half_y, cy);
    }
    btBoxShape* ground_shape = box(half_x, half_y, ground_half_thickness);
    addFixedBody(ground_shape, planarTransform(cx - ox, cy - oy, -ground_half_thickness, 0),
                 physics.ground_friction, kGroundGroup, kGroundMask, kNotObstacle);

    // Parked robots enter as fixed boxes and become dynamic when the robot comes near (wake()).
    // In worlds with many of them, each enters Bullet only when the robot comes within
    // parked_insert_distance_m: Bullet loops over every object it holds at every step.
    std::size_t parked_count = 0;
    for (const Obstacle& o : obstacles) parked_count += o.kind == ObstacleKind::kParkedRobot;
    lazy = parked_count > model.parked_lazy_count;
    cell = model.parked_insert_distance_m;
    bodies.resize(obstacles.size() + 1);
    for (std::size_t i = 0; i < obstacles.size(); ++i) {
      if (lazy && obstacles[i].kind == ObstacleKind::kParkedRobot) continue;
      insertObstacle(i);
    }
    if (lazy) buildGrid();
  }

  // The obstacle's shape in a frame at its box centre (for circles and polygons, the centre
  // of their bounding rectangle) with the box's yaw.
  btCollisionShape* obstacleShape(const Obstacle& o) {
    const double hz = 0.5 * o.height_m;
    switch (o.shape) {
      case ObstacleShape::kBox: break;
      case ObstacleShape::kCircle: {
        const auto r = btScalar(o.radius_m);
        auto shape = std::make_unique<btCylinderShapeZ>(btVector3(r, r, btScalar(hz)));
        // btCylinderShape keeps its outer size when the margin changes.
        shape->setMargin(btScalar(std::min(kShapeMargin_m, 0.5 * o.radius_m)));
        btCollisionShape* raw = shape.get();
        shapes.push_back(std::move(shape));
        return raw;
      }
      case ObstacleShape::kPolygon: {
        auto shape = std::make_unique<btConvexHullShape>();
        const double margin = std::min(
            kShapeMargin_m, 0.25 * std::min(o.box.half_extents.x(), o.box.half_extents.y()));
        for (const Eigen::Vector2d& v : insetPolygon(o.vertices, margin)) {
          const Eigen::Vector2d d = v - o.box.center;
          for (const double z : {-(hz - margin), hz - margin}) {
            shape->addPoint(btVector3(btScalar(d.x()), btScalar(d.y()), btScalar(z)), false);
          }
        }
        shape->recalcLocalAabb();
        shape->setMargin(btScalar(margin));
        btCollisionShape* raw = shape.get();
        shapes.push_back(std::move(shape));
        return raw;
      }
    }
    return box(o.box.half_extents.x(), o.box.half_extents.y(), hz);
  }

  void buildRobot(const Pose2& start) {
    const double r = robot.wheel_radius_m;
    const double half_track = 0.5 * true_track;
    const double bottom = robot.ground_clearance_m;
    const double top = robot.height_m;
    chassis_dx = robot.footprintCenterOffset();
    chassis_z = 0.5 * (bottom + top);

    btBoxShape* chassis_shape =
        box(0.5 * robot.length_m, 0.5 * robot.width_m, 0.5 * (top - bottom));
    btVector3 chassis_inertia;
    chassis_shape->calculateLocalInertia(btScalar(physics.chassis_mass_kg), chassis_inertia);
    btSphereShape* wheel_shape = sphere(r);
    btVector3 wheel_inertia;
    wheel_shape->calculateLocalInertia(btScalar(physics.wheel_mass_kg), wheel_inertia);
    // Wheels of another true radius: their own spheres, centres at their own height, so the
    // chassis rolls slightly, as a real robot with unequal wheels does.
    const bool exact_wheels = left_radius == r && right_radius == r;
    btSphereShape* left_shape = exact_wheels ? wheel_shape : sphere(left_radius);
    btSphereShape* right_shape = exact_wheels ? wheel_shape : sphere(right_radius);
    btVector3 left_inertia = wheel_inertia;
    btVector3 right_inertia = wheel_inertia;
    if (!exact_wheels) {
      left_shape->calculateLocalInertia(btScalar(physics.wheel_mass_kg), left_inertia);
      right_shape->calculateLocalInertia(btScalar(physics.wheel_mass_kg), right_inertia);
    }
    if (model.body.wheel_axle_inertia_kgm2 > 0.0) {  // the axle is the link's y axis
      left_inertia.setY(btScalar(model.body.wheel_axle_inertia_kgm2));
      right_inertia.setY(btScalar(model.body.wheel_axle_inertia_kgm2));
    }
    btSphereShape* support_shape = sphere(model.support_radius_m);
    btVector3 support_inertia;
    support_shape->calculateLocalInertia(btScalar(model.support_mass_kg), support_inertia);

    // The base is the chassis box, its frame at the box centre (its centre of mass).
    ego = std::make_unique<btMultiBody>(3, btScalar(physics.chassis_mass_kg), chassis_inertia,
                                        /*fixedBase=*/false, /*canSleep=*/false);
    const btQuaternion no_rotation(0, 0, 0, 1);
    const btVector3 no_offset(0, 0, 0);
    // Axis +y (to the robot's left): a positive joint speed rolls the contact point backwards,
    // so positive drives the robot forward, as WheelSpeeds require.
    const btVector3 axle(0, 1, 0);
    const double axle_dx = -chassis_dx;  // reference point relative to the chassis centre
    const double axle_dz = r - chassis_z;
    const double left_dz = exact_wheels ? axle_dz : left_radius - chassis_z;
    const double right_dz = exact_wheels ? axle_dz : right_radius - chassis_z;
    ego->setupRevolute(kLeftWheel, btScalar(physics.wheel_mass_kg), left_inertia, -1, no_rotation,
                       axle, btVector3(btScalar(axle_dx), btScalar(half_track), btScalar(left_dz)),
                       no_offset, true);
    ego->setupRevolute(
        kRightWheel, btScalar(physics.wheel_mass_kg), right_inertia, -1, no_rotation, axle,
        btVector3(btScalar(axle_dx), btScalar(-half_track), btScalar(right_dz)), no_offset, true);
    const double rear_edge = robot.front_overhang_m - robot.length_m;  // from the reference point
    const double support_x = rear_edge + model.support_inset_m - chassis_dx;
    const double support_z = model.support_radius_m - chassis_z;
    ego->setupFixed(kSupport, btScalar(model.support_mass_kg), support_inertia, -1, no_rotation,
                    btVector3(btScalar(support_x), 0, btScalar(support_z)), no_offset, true);
    ego->finalizeMultiDof();
    // btMultiBody damps by default (0.04); an undamped model is what the plan assumes.
    ego->setLinearDamping(0);
    ego->setAngularDamping(0);
    ego->setHasSelfCollision(false);

    const double c = std::cos(start.theta);
    const double s = std::sin(start.theta);
    ego->setBaseWorldTransform(planarTransform(
        start.x - ox + chassis_dx * c, start.y - oy + chassis_dx * s, chassis_z, start.theta));
    world->addMultiBody(ego.get());

    auto add_collider = [&](int link, btCollisionShape* shape, double friction, int group,
                            int mask) {
      auto collider = std::make_unique<btMultiBodyLinkCollider>(ego.get(), link);
      collider->setCollisionShape(shape);
      collider->setFriction(btScalar(friction));
      collider->setUserIndex(kNotObstacle);
      if (link >= 0)
        collider->setContactProcessingThreshold(btScalar(model.wheel_contact_processing_m));
      world->addCollisionObject(collider.get(), group, mask);
      if (link < 0) {
        ego->setBaseCollider(collider.get());
      } else {
        ego->getLink(link).m_collider = collider.get();
      }
      colliders.push_back(std::move(collider));
    };
    add_collider(-1, chassis_shape, physics.obstacle_friction, kChassisGroup, kChassisMask);
    add_collider(kLeftWheel, left_shape, physics.wheel_friction, kWheelGroup, kWheelMask);
    add_collider(kRightWheel, right_shape, physics.wheel_friction, kWheelGroup, kWheelMask);
    add_collider(kSupport, support_shape, physics.support_friction, kWheelGroup, kWheelMask);

    btAlignedObjectArray<btQuaternion> scratch_q;
    btAlignedObjectArray<btVector3> scratch_v;
    ego->forwardKinematics(scratch_q, scratch_v);
    ego->updateCollisionObjectWorldTransforms(scratch_q, scratch_v);

    // Motor limits are impulses per step: torque x dt. Driven by torque, the "motor" is the
    // drive train's Coulomb friction: a target of zero speed that at most that torque holds.
    const bool torque_drive = model.body.drive == WheelDrive::kTorque;
    if (torque_drive && !(model.body.joint_friction_nm > 0.0)) return;
    const btScalar max_impulse =
        btScalar((torque_drive ? model.body.joint_friction_nm : physics.max_wheel_torque_nm) *
                 physics.time_step_s);
    for (int link : {kLeftWheel, kRightWheel}) {
      auto motor = std::make_unique<btMultiBodyJointMotor>(ego.get(), link, 0, max_impulse);
      world->addMultiBodyConstraint(motor.get());
      motors.push_back(std::move(motor));
    }
  }

  // Turns a parked robot from a fixed box into a body with mass, keeping its pose. Re-adding
  // it makes the broadphase and the solver treat it as dynamic from the next step on.
  void wake(int obstacle_index) {
    btRigidBody* body = bodies[static_cast<std::size_t>(obstacle_index) + 1].get();
    if (body == nullptr) return;
    if (!body->isStaticObject()) return;
    world->removeRigidBody(body);
    const Obstacle& o = obstacles[static_cast<std::size_t>(obstacle_index)];
    const auto mass = btScalar(o.mass_kg.value_or(physics.parked_robot_mass_kg));
    btVector3 inertia;
    body->getCollisionShape()->calculateLocalInertia(mass, inertia);
    body->setCollisionFlags(body->getCollisionFlags() & ~btCollisionObject::CF_STATIC_OBJECT);
    body->setMassProps(mass, inertia);
    body->updateInertiaTensor();
    body->setSleepingThresholds(btScalar(model.parked_sleep_speed_mps),
                                btScalar(model.parked_sleep_yaw_rate_radps));
    world->addRigidBody(body, kParkedGroup, kParkedMask);
    body->activate(true);
  }

  void collectContacts() {
    contacts.clear();
    const btCollisionObject* chassis = colliders.front().get();
    const int n = dispatcher->getNumManifolds();
    for (int i = 0; i < n; ++i) {
      const btPersistentManifold* m = dispatcher->getManifoldByIndexInternal(i);
      const btCollisionObject* other = nullptr;
      if (m->getBody0() == chassis) other = m->getBody1();
      if (m->getBody1() == chassis) other = m->getBody0();
      if (other == nullptr || other->getUserIndex() == kNotObstacle) continue;
      for (int p = 0; p < m->getNumContacts(); ++p) {
        if (m->getContactPoint(p).getDistance() < 0) {
          contacts.push_back(other->getUserIndex());
          break;
        }
      }
    }
    std::sort(contacts.begin(), contacts.end());
    contacts.erase(std::unique(contacts.begin(), contacts.end()), contacts.end());
  }

  // The robot's state after the last step (Episode reads it two or three times a step).
  RobotState computeRobot() const {
    const Impl& d = *this;
    const btTransform base = d.ego->getBaseWorldTransform();
    const btVector3 ref_local(btScalar(-d.chassis_dx), 0,
                              btScalar(d.robot.wheel_radius_m - d.chassis_z));
    const btVector3 ref = base * ref_local;
    RobotState out;
    out.local_pose = {double(ref.x()), double(ref.y()), yawOf(base)};
    out.pose = {out.local_pose.x + d.ox, out.local_pose.y + d.oy, out.local_pose.theta};
    out.axle_height_m = double(ref.z());
    const btVector3 up = base.getBasis().getColumn(2);
    out.tilt_rad = std::acos(std::clamp(double(up.z()), -1.0, 1.0));
    const btVector3 omega = d.ego->getBaseOmega();
    const btVector3 vel = d.ego->getBaseVel() + omega.cross(ref - base.getOrigin());
    out.twist = {
        double(vel.x()) * std::cos(out.pose.theta) + double(vel.y()) * std::sin(out.pose.theta),
        double(omega.z())};
    out.wheels = {double(d.ego->getJointVel(kLeftWheel)), double(d.ego->getJointVel(kRightWheel))};
    out.wheel_angles = {double(d.ego->getJointPos(kLeftWheel)),
                        double(d.ego->getJointPos(kRightWheel))};
    const double yaw_rate = double(omega.z());
    out.slip_mps = {
        out.wheels.left_radps * d.left_radius - (out.twist.v_mps - 0.5 * d.true_track * yaw_rate),
        out.wheels.right_radps * d.right_radius -
            (out.twist.v_mps + 0.5 * d.true_track * yaw_rate)};
    out.awake = d.ego->isAwake();
    return out;
  }

  // Gives a parked robot its mass while the chassis is still model.parked_wake_distance_m away,
  // so the first contact is already between two bodies with mass.
  // Candidates come from the broadphase (the footprint's bounding box grown by the wake
  // distance against every proxy's box), so parked robots far away cost nothing per step.
  void wakeNearbyParkedRobots(const Pose2& ego_pose) {
    if (lazy) insertNearbyParkedRobots(ego_pose);
    const OrientedBox footprint = footprintAt(robot, ego_pose);
    const double c = std::abs(std::cos(footprint.yaw));
    const double sn = std::abs(std::sin(footprint.yaw));
    const Eigen::Vector2d ext(c * footprint.half_extents.x() + sn * footprint.half_extents.y(),
                              sn * footprint.half_extents.x() + c * footprint.half_extents.y());
    const double grow = model.parked_wake_distance_m;
    const btVector3 lo(btScalar(footprint.center.x() - ext.x() - grow - ox),
                       btScalar(footprint.center.y() - ext.y() - grow - oy), btScalar(-1.0));
    const btVector3 hi(btScalar(footprint.center.x() + ext.x() + grow - ox),
                       btScalar(footprint.center.y() + ext.y() + grow - oy),
                       btScalar(robot.height_m + 1.0));
    struct Collect : btBroadphaseAabbCallback {
      std::vector<int>* out = nullptr;
      bool process(const btBroadphaseProxy* proxy) override {
        const auto* object = static_cast<const btCollisionObject*>(proxy->m_clientObject);
        if ((proxy->m_collisionFilterGroup & kParkedGroup) != 0 && object->isStaticObject()) {
          out->push_back(object->getUserIndex());
        }
        return true;
      }
    } collect;
    candidates.clear();
    collect.out = &candidates;
    broadphase->aabbTest(lo, hi, collect);
    // Scenario order, as a loop over all of them would wake them (the order bodies are added
    // in is the order the solver sees them).
    std::sort(candidates.begin(), candidates.end());
    for (int index : candidates) {
      const auto i = static_cast<std::size_t>(index);
      if (!blocksRobot(obstacles[i], robot)) continue;
      // The separating-axis gap is a lower bound of the true gap: it wakes early, never late.
      if (separationAlongAxes(footprint, obstacles[i].box) < model.parked_wake_distance_m) {
        wake(index);
        woken.push_back(index);
      }
    }
  }
};

DynamicsWorld::DynamicsWorld(const Scenario& scenario, const Pose2& start, const SimModelDef& model)
    : impl_(std::make_unique<Impl>()) {
  const PhysicsDef& p = scenario.physics;
  const RobotDef& r = scenario.robot;
  requirePositive(p.time_step_s, "physics.time_step_s");
  requirePositive(p.solver_iterations, "physics.solver_iterations");
  requirePositive(p.chassis_mass_kg, "physics.chassis_mass_kg");
  requirePositive(p.wheel_mass_kg, "physics.wheel_mass_kg");
  requirePositive(p.parked_robot_mass_kg, "physics.parked_robot_mass_kg");
  requirePositive(p.max_wheel_torque_nm, "physics.max_wheel_torque_nm");
  requirePositive(r.length_m, "robot.length_m");
  requirePositive(r.width_m, "robot.width_m");
  requirePositive(r.wheel_radius_m, "robot.wheel_radius_m");
  requirePositive(r.wheel_base_m, "robot.wheel_base_m");
  requirePositive(model.support_radius_m, "support_radius_m");
  requirePositive(model.support_mass_kg, "support_mass_kg");
  requirePositive(model.wheel_contact_processing_m, "wheel_contact_processing_m");
  if (!(model.solver_residual_threshold >= 0.0)) {
    throw Error("simulation: solver_residual_threshold must not be negative");
  }
  requirePositive(r.height_m - r.ground_clearance_m, "robot height above the clearance");
  if (!(r.ground_clearance_m >= 0.0)) throw Error("simulation: robot ground clearance < 0");
  for (const Obstacle& o : scenario.obstacles) {
    requirePositive(o.box.half_extents.x(), (o.name + " half length").c_str());
    requirePositive(o.box.half_extents.y(), (o.name + " half width").c_str());
    requirePositive(o.height_m, (o.name + " height").c_str());
    if (o.shape == ObstacleShape::kCircle)
      requirePositive(o.radius_m, (o.name + " radius").c_str());
    if (o.shape == ObstacleShape::kPolygon && !isStrictlyConvexCcw(o.vertices)) {
      throw Error("simulation: " + o.name + " must be a convex counter-clockwise polygon");
    }
    if (o.mass_kg) requirePositive(*o.mass_kg, (o.name + " mass").c_str());
  }
  impl_->robot = r;
  impl_->physics = p;
  impl_->model = model;
  impl_->obstacles = scenario.obstacles;
  impl_->lot = scenario.lot;
  const TrueRobotDef& body = model.body;
  requirePositive(body.left_radius_scale, "left_radius_scale");
  requirePositive(body.right_radius_scale, "right_radius_scale");
  requirePositive(body.track_scale, "track_scale");
  if (!(body.wheel_axle_inertia_kgm2 >= 0.0) || !(body.joint_friction_nm >= 0.0)) {
    throw Error("simulation: wheel_axle_inertia_kgm2 and joint_friction_nm must not be negative");
  }
  requirePositive(model.local_frame_grid_m, "local_frame_grid_m");
  impl_->left_radius = r.wheel_radius_m * body.left_radius_scale;
  impl_->right_radius = r.wheel_radius_m * body.right_radius_scale;
  impl_->true_track = r.wheel_base_m * body.track_scale;
  impl_->ox = model.local_frame_grid_m * std::floor(start.x / model.local_frame_grid_m);
  impl_->oy = model.local_frame_grid_m * std::floor(start.y / model.local_frame_grid_m);
  impl_->buildWorld();
  impl_->buildRobot(start);
  impl_->state = impl_->computeRobot();
  impl_->wakeNearbyParkedRobots(start);
}

DynamicsWorld::~DynamicsWorld() = default;

void DynamicsWorld::setWheelTargets(const WheelSpeeds& targets) {
  impl_->targets = targets;
  if (impl_->model.body.drive != WheelDrive::kVelocityMotor) return;
  impl_->motors[kLeftWheel]->setVelocityTarget(btScalar(targets.left_radps));
  impl_->motors[kRightWheel]->setVelocityTarget(btScalar(targets.right_radps));
}

const WheelSpeeds& DynamicsWorld::wheelTargets() const { return impl_->targets; }

void DynamicsWorld::setWheelTorques(const WheelSpeeds& torques_nm) { impl_->torques = torques_nm; }

double DynamicsWorld::leftWheelRadius() const { return impl_->left_radius; }
double DynamicsWorld::rightWheelRadius() const { return impl_->right_radius; }
double DynamicsWorld::track() const { return impl_->true_track; }

void DynamicsWorld::step() {
  const btScalar dt = btScalar(impl_->physics.time_step_s);
  if (impl_->model.body.drive == WheelDrive::kTorque) {
    // Bullet clears joint torques after every step.
    impl_->ego->addJointTorque(kLeftWheel, btScalar(impl_->torques.left_radps));
    impl_->ego->addJointTorque(kRightWheel, btScalar(impl_->torques.right_radps));
  }
  // One internal step of exactly dt: the default arguments would step at 1/60 s and
  // interpolate.
  impl_->world->stepSimulation(dt, 1, dt);
  ++impl_->step_count;
  impl_->collectContacts();
  impl_->state = impl_->computeRobot();
  impl_->wakeNearbyParkedRobots(impl_->state.pose);
}

double DynamicsWorld::timeStep() const { return impl_->physics.time_step_s; }

double DynamicsWorld::time() const {
  return static_cast<double>(impl_->step_count) * impl_->physics.time_step_s;
}

long DynamicsWorld::steps() const { return impl_->step_count; }

const RobotState& DynamicsWorld::robot() const { return impl_->state; }

std::vector<Pose2> DynamicsWorld::obstaclePoses() const {
  std::vector<Pose2> poses;
  poses.reserve(impl_->obstacles.size());
  for (std::size_t i = 0; i < impl_->obstacles.size(); ++i) {
    const btTransform tr = impl_->obstacleWorldTransform(i);
    poses.push_back({double(tr.getOrigin().x()) + impl_->ox, double(tr.getOrigin().y()) + impl_->oy,
                     yawOf(tr)});
  }
  return poses;
}

Eigen::Vector2d DynamicsWorld::obstaclePosition(std::size_t index) const {
  const btVector3 origin = impl_->obstacleWorldTransform(index).getOrigin();
  return {double(origin.x()) + impl_->ox, double(origin.y()) + impl_->oy};
}

std::vector<double> DynamicsWorld::obstacleHeights() const {
  std::vector<double> heights;
  heights.reserve(impl_->obstacles.size());
  for (std::size_t i = 0; i < impl_->obstacles.size(); ++i) {
    heights.push_back(double(impl_->obstacleWorldTransform(i).getOrigin().z()));
  }
  return heights;
}

const std::vector<int>& DynamicsWorld::chassisContacts() const { return impl_->contacts; }

const std::vector<int>& DynamicsWorld::movableObstacles() const { return impl_->woken; }

}  // namespace parksim
