#include "parksim/sim/world/DynamicsWorld.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <BulletCollision/BroadphaseCollision/btDbvtBroadphase.h>
#include <BulletCollision/CollisionDispatch/btCollisionDispatcher.h>
#include <BulletCollision/CollisionDispatch/btDefaultCollisionConfiguration.h>
#include <BulletCollision/CollisionShapes/btBoxShape.h>
#include <BulletDynamics/Dynamics/btRigidBody.h>
#include <BulletDynamics/Featherstone/btMultiBodyDynamicsWorld.h>

#include "parksim/core/io/Error.h"
#include "parksim/core/model/Geometry.h"
#include "parksim/core/system/ProvenanceConfig.h"
#include "parksim/sim/contacts/ChassisContacts.h"
#include "parksim/sim/contacts/CollisionGroups.h"
#include "parksim/sim/world/BulletFrames.h"
#include "parksim/sim/world/CarBody.h"
#include "parksim/sim/world/GroundSlab.h"
#include "parksim/sim/world/KernelParts.h"
#include "parksim/sim/world/ObstacleBodies.h"
#include "parksim/sim/world/RobotBody.h"

namespace parksim {

// Result files record Bullet's precision (parksim/core/system/Provenance.h); it must be the one
// compiled.
static_assert(sizeof(btScalar) == (PARKSIM_BULLET_DOUBLE ? sizeof(double) : sizeof(float)),
              "cmake/Provenance.cmake and Bullet's headers disagree on BT_USE_DOUBLE_PRECISION");

namespace {

void requirePositive(double value, const char* what) {
  if (!(value > 0.0) || !std::isfinite(value)) {
    throw Error(std::string("simulation: ") + what + " must be positive, got " +
                std::to_string(value));
  }
}

void validate(const Scenario& scenario, const SimModelDef& model) {
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
  requirePositive(model.cold_solver_iterations, "cold_solver_iterations");
  requirePositive(model.support_radius_m, "support_radius_m");
  requirePositive(model.support_mass_kg, "support_mass_kg");
  requirePositive(model.support_deflection_m, "support_clearance_m");
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
    if (o.shape == ObstacleShape::kCompound && (!o.compound || o.compound->parts.empty())) {
      throw Error("simulation: " + o.name + " must have convex parts");
    }
    if (o.mass_kg) requirePositive(*o.mass_kg, (o.name + " mass").c_str());
  }
  const TrueRobotDef& body = model.body;
  requirePositive(body.left_radius_scale, "left_radius_scale");
  requirePositive(body.right_radius_scale, "right_radius_scale");
  requirePositive(body.track_scale, "track_scale");
  if (!(body.wheel_axle_inertia_kgm2 >= 0.0) || !(body.joint_friction_nm >= 0.0)) {
    throw Error("simulation: wheel_axle_inertia_kgm2 and joint_friction_nm must not be negative");
  }
  requirePositive(model.local_frame_grid_m, "local_frame_grid_m");
  if (r.isCar()) {
    requirePositive(r.axle_distance_m, "robot.axle_distance_m");
    requirePositive(r.max_steer_rad, "robot.max_steer_rad");
    requirePositive(r.max_steer_rate_radps, "robot.max_steer_rate_radps");
    requirePositive(model.car.tyre_deflection_per_radius, "car tyre_deflection_per_radius");
    requirePositive(model.car.knuckle_mass_fraction, "car knuckle_mass_fraction");
    if (!(model.car.steer_position_gain > 0.0 && model.car.steer_position_gain <= 1.0)) {
      throw Error("simulation: car steer_position_gain must lie in (0, 1]");
    }
  }
}

}  // namespace

Pose2 localFrameOrigin(const Pose2& start, double grid_m) {
  return {grid_m * std::floor(start.x / grid_m), grid_m * std::floor(start.y / grid_m), 0.0};
}

namespace {
Eigen::Vector2d originXY(const Pose2& origin) { return {origin.x, origin.y}; }
}  // namespace

struct DynamicsWorld::Impl {
  Impl(const Scenario& scenario, const Pose2& start, const SimModelDef& m)
      : physics(scenario.physics),
        model(m),
        origin(originXY(localFrameOrigin(start, m.local_frame_grid_m))),
        car(scenario.robot.isCar()) {
    buildWorld();
    addGround(scenario.lot);
    obstacles.emplace(*world, scenario.obstacles, scenario.robot, physics, model, origin);
    if (scenario.robot.isCar()) {
      robot = std::make_unique<CarBody>(*world, scenario.robot, physics, model, start, origin);
    } else {
      robot = std::make_unique<RobotBody>(*world, scenario.robot, physics, model, start, origin,
                                          *kernel);
    }
    state = robot->state();
    obstacles->wakeNear(start);
  }

  PhysicsDef physics;
  SimModelDef model;
  Eigen::Vector2d origin;
  bool car;

  // Destroyed in reverse order: the robot and the bodies leave the world before it goes.
  std::unique_ptr<btDefaultCollisionConfiguration> config;
  std::unique_ptr<btCollisionDispatcher> dispatcher;
  std::unique_ptr<btOverlapFilterCallback> pair_filter;  // outlives the broadphase
  std::unique_ptr<btDbvtBroadphase> broadphase;
  std::optional<KernelParts> kernel;  // the solver; outlives the world and the robot's motors
  std::unique_ptr<btMultiBodyDynamicsWorld> world;
  std::unique_ptr<btBoxShape> ground_shape;
  std::unique_ptr<btRigidBody> ground;
  std::optional<ObstacleBodies> obstacles;
  std::unique_ptr<EgoBody> robot;

  WheelSpeeds targets;
  double steer_target = 0.0;
  WheelSpeeds torques;
  RobotState state;
  long step_count = 0;
  std::vector<int> contacts;

  ~Impl() {
    robot.reset();
    obstacles.reset();
    if (ground) world->removeRigidBody(ground.get());
  }

  void buildWorld() {
    // Pools for a robot and its lot's neighbours, not Bullet's default 4,096 contacts: those
    // cost ~20 ms of CPU a world to allocate and touch (43 ms less for a run's two worlds), and
    // beyond a pool Bullet takes the heap.
    btDefaultCollisionConstructionInfo pools;
    pools.m_defaultMaxPersistentManifoldPoolSize = 64;
    pools.m_defaultMaxCollisionAlgorithmPoolSize = 64;
    config = std::make_unique<btDefaultCollisionConfiguration>(pools);
    dispatcher = std::make_unique<btCollisionDispatcher>(config.get());
    // A car's friction rows start cold: warm-started, its chassis kept rocking at rest at
    // 1-6 mm/s (docs/simulation.md, "A car in Bullet").
    kernel.emplace(model, *dispatcher, /*warm_start_friction=*/!car);
    pair_filter = makeFixedObstaclePairFilter();
    broadphase = std::make_unique<btDbvtBroadphase>();
    broadphase->getOverlappingPairCache()->setOverlapFilterCallback(pair_filter.get());
    world = kernel->makeWorld(*dispatcher, *broadphase, *config);
    world->setGravity(btVector3(0, 0, btScalar(-physics.gravity_mps2)));
    world->getSolverInfo().m_numIterations = kernel->solverIterations(
        car ? std::max(physics.solver_iterations, model.car.min_solver_iterations)
            : physics.solver_iterations);
    world->getSolverInfo().m_leastSquaresResidualThreshold =
        btScalar(model.solver_residual_threshold);
    // Bullet warm-starts rigid bodies' contacts (woken parked robots) at 85 % of their last
    // impulses; with the robot's rows converging in a few iterations the early exit comes
    // sooner, and a resting parked robot rebuilding 15 % of its support every step crept by up
    // to 13 um. At 100 % it stays put to the last bit, as before.
    if (model.warm_start) world->getSolverInfo().m_warmstartingFactor = 1;
    // Bullet recomputes every object's bounding box every step by default, fixed ones
    // included. Fixed bodies get theirs once (addFixedBody: updateSingleAabb adds the contact
    // threshold exactly as the per-step update did); moving bodies are still updated.
    world->setForceUpdateAllAabbs(false);
  }

  void addGround(const LotBounds& lot) {
    const GroundSlab slab =
        groundSlab(lot, model.has_reach ? std::optional<LotBounds>(model.reach) : std::nullopt,
                   model.ground_margin_m);
    ground_shape = std::make_unique<btBoxShape>(btVector3(btScalar(slab.half_extents.x()),
                                                          btScalar(slab.half_extents.y()),
                                                          btScalar(slab.half_thickness_m)));
    ground = addFixedBody(*world, ground_shape.get(),
                          planarTransform(slab.center.x() - origin.x(),
                                          slab.center.y() - origin.y(), -slab.half_thickness_m, 0),
                          physics.ground_friction, kGroundGroup, kGroundMask, kNotObstacle);
  }
};

DynamicsWorld::DynamicsWorld(const Scenario& scenario, const Pose2& start,
                             const SimModelDef& model) {
  validate(scenario, model);
  impl_ = std::make_unique<Impl>(scenario, start, model);
}

DynamicsWorld::~DynamicsWorld() = default;

void DynamicsWorld::setWheelTargets(const WheelSpeeds& targets) {
  impl_->targets = targets;
  impl_->robot->setWheelTargets(targets);
}

const WheelSpeeds& DynamicsWorld::wheelTargets() const { return impl_->targets; }

void DynamicsWorld::setSteerTarget(double steer_rad) {
  impl_->steer_target = steer_rad;
  impl_->robot->setSteerTarget(steer_rad);
}

double DynamicsWorld::steerTarget() const { return impl_->steer_target; }

void DynamicsWorld::setWheelTorques(const WheelSpeeds& torques_nm) { impl_->torques = torques_nm; }

double DynamicsWorld::leftWheelRadius() const { return impl_->robot->leftRadius(); }
double DynamicsWorld::rightWheelRadius() const { return impl_->robot->rightRadius(); }
double DynamicsWorld::track() const { return impl_->robot->track(); }

void DynamicsWorld::step() {
  Impl& d = *impl_;
  const btScalar dt = btScalar(d.physics.time_step_s);
  if (d.model.body.drive == WheelDrive::kTorque) d.robot->addWheelTorques(d.torques);
  d.robot->beforeStep(d.physics.time_step_s);
  // One internal step of exactly dt: the default arguments would step at 1/60 s and
  // interpolate.
  d.world->stepSimulation(dt, 1, dt);
  ++d.step_count;
  collectChassisContacts(*d.dispatcher, d.robot->chassis(), d.contacts);
  d.state = d.robot->state();
  d.obstacles->wakeNear(d.state.pose);
}

double DynamicsWorld::timeStep() const { return impl_->physics.time_step_s; }

double DynamicsWorld::time() const {
  return static_cast<double>(impl_->step_count) * impl_->physics.time_step_s;
}

long DynamicsWorld::steps() const { return impl_->step_count; }

const RobotState& DynamicsWorld::robot() const { return impl_->state; }

std::vector<Pose2> DynamicsWorld::obstaclePoses() const {
  const Impl& d = *impl_;
  std::vector<Pose2> poses;
  poses.reserve(d.obstacles->size());
  for (std::size_t i = 0; i < d.obstacles->size(); ++i) {
    const btTransform tr = d.obstacles->transform(i);
    poses.push_back({double(tr.getOrigin().x()) + d.origin.x(),
                     double(tr.getOrigin().y()) + d.origin.y(), yawOf(tr)});
  }
  return poses;
}

Eigen::Vector2d DynamicsWorld::obstaclePosition(std::size_t index) const {
  const btVector3 origin = impl_->obstacles->transform(index).getOrigin();
  return {double(origin.x()) + impl_->origin.x(), double(origin.y()) + impl_->origin.y()};
}

std::vector<double> DynamicsWorld::obstacleHeights() const {
  std::vector<double> heights;
  heights.reserve(impl_->obstacles->size());
  for (std::size_t i = 0; i < impl_->obstacles->size(); ++i) {
    heights.push_back(double(impl_->obstacles->transform(i).getOrigin().z()));
  }
  return heights;
}

const std::vector<int>& DynamicsWorld::chassisContacts() const { return impl_->contacts; }

const std::vector<int>& DynamicsWorld::movableObstacles() const {
  return impl_->obstacles->woken();
}

}  // namespace parksim
