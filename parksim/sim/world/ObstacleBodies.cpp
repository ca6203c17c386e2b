#include "parksim/sim/world/ObstacleBodies.h"

#include <algorithm>
#include <cmath>

#include <BulletCollision/BroadphaseCollision/btBroadphaseInterface.h>
#include <BulletCollision/CollisionShapes/btCollisionShape.h>
#include <BulletDynamics/Dynamics/btRigidBody.h>
#include <BulletDynamics/Featherstone/btMultiBodyDynamicsWorld.h>

#include "parksim/collision/ObstacleShape.h"
#include "parksim/core/model/Geometry.h"
#include "parksim/sim/contacts/CollisionGroups.h"
#include "parksim/sim/world/BulletFrames.h"

namespace parksim {

std::unique_ptr<btRigidBody> addFixedBody(btMultiBodyDynamicsWorld& world, btCollisionShape* shape,
                                          const btTransform& transform, double friction, int group,
                                          int mask, int user_index) {
  btRigidBody::btRigidBodyConstructionInfo info(0, nullptr, shape, btVector3(0, 0, 0));
  info.m_startWorldTransform = transform;
  info.m_friction = btScalar(friction);
  info.m_linearDamping = 0;
  info.m_angularDamping = 0;
  auto body = std::make_unique<btRigidBody>(info);
  body->setUserIndex(user_index);
  world.addRigidBody(body.get(), group, mask);
  world.updateSingleAabb(body.get());
  return body;
}

ObstacleBodies::ObstacleBodies(btMultiBodyDynamicsWorld& world,
                               const std::vector<Obstacle>& obstacles, const RobotDef& robot,
                               const PhysicsDef& physics, const SimModelDef& model,
                               const Eigen::Vector2d& origin)
    : world_(world),
      model_(model),
      obstacles_(obstacles),
      robot_(robot),
      friction_(physics.obstacle_friction),
      default_parked_mass_kg_(physics.parked_robot_mass_kg),
      origin_(origin) {
  std::size_t parked_count = 0;
  for (const Obstacle& o : obstacles_) parked_count += o.kind == ObstacleKind::kParkedRobot;
  const bool lazy = parked_count > model_.parked_lazy_count;
  bodies_.resize(obstacles_.size());
  for (std::size_t i = 0; i < obstacles_.size(); ++i) {
    if (lazy && obstacles_[i].kind == ObstacleKind::kParkedRobot) continue;
    insert(i);
  }
  if (lazy) grid_.emplace(obstacles_, model_.parked_insert_distance_m);
}

ObstacleBodies::~ObstacleBodies() {
  for (auto& body : bodies_) {
    if (body) world_.removeRigidBody(body.get());
  }
}

btTransform ObstacleBodies::placement(std::size_t i) const {
  const Obstacle& o = obstacles_[i];
  return planarTransform(o.box.center.x() - origin_.x(), o.box.center.y() - origin_.y(),
                         0.5 * o.height_m, o.box.yaw);
}

btTransform ObstacleBodies::transform(std::size_t i) const {
  const btRigidBody* body = bodies_[i].get();
  return body != nullptr ? body->getWorldTransform() : placement(i);
}

void ObstacleBodies::insert(std::size_t i) {
  const Obstacle& o = obstacles_[i];
  shapes_.push_back(makeObstacleShape(o, kContactObstacleShapes));
  const bool parked = o.kind == ObstacleKind::kParkedRobot;
  // Obstacles no higher than the ground clearance pass under the chassis (blocksRobot); they
  // are in the world to be seen, and collide with nothing.
  const bool blocks = blocksRobot(o, robot_);
  bodies_[i] = addFixedBody(world_, shapes_.back().get(), placement(i), friction_,
                            parked ? kParkedGroup : kStaticGroup,
                            !blocks  ? 0
                            : parked ? kParkedMask
                                     : kStaticMask,
                            static_cast<int>(i));
}

// Asks the grid again only after the robot moved a quarter of a cell, so a step costs O(1)
// however many parked robots the world has.
void ObstacleBodies::insertNear(const Pose2& ego_pose) {
  const Eigen::Vector2d p(ego_pose.x, ego_pose.y);
  if (last_query_ && (p - *last_query_).norm() < 0.25 * grid_->cell()) return;
  last_query_ = p;
  const double reach = grid_->cell() + robot_.length_m + robot_.width_m;
  for (int i : grid_->near(p, reach)) {
    if (!bodies_[static_cast<std::size_t>(i)]) insert(static_cast<std::size_t>(i));
  }
}

// Re-adding the body makes the broadphase and the solver treat it as dynamic from the next
// step on.
void ObstacleBodies::wake(std::size_t i) {
  btRigidBody* body = bodies_[i].get();
  if (body == nullptr) return;
  if (!body->isStaticObject()) return;
  world_.removeRigidBody(body);
  const auto mass = btScalar(obstacles_[i].mass_kg.value_or(default_parked_mass_kg_));
  btVector3 inertia;
  body->getCollisionShape()->calculateLocalInertia(mass, inertia);
  body->setCollisionFlags(body->getCollisionFlags() & ~btCollisionObject::CF_STATIC_OBJECT);
  body->setMassProps(mass, inertia);
  body->updateInertiaTensor();
  body->setSleepingThresholds(btScalar(model_.parked_sleep_speed_mps),
                              btScalar(model_.parked_sleep_yaw_rate_radps));
  world_.addRigidBody(body, kParkedGroup, kParkedMask);
  body->activate(true);
}

void ObstacleBodies::wakeNear(const Pose2& ego_pose) {
  if (grid_) insertNear(ego_pose);
  const OrientedBox footprint = footprintAt(robot_, ego_pose);
  const double c = std::abs(std::cos(footprint.yaw));
  const double sn = std::abs(std::sin(footprint.yaw));
  const Eigen::Vector2d ext(c * footprint.half_extents.x() + sn * footprint.half_extents.y(),
                            sn * footprint.half_extents.x() + c * footprint.half_extents.y());
  const double grow = model_.parked_wake_distance_m;
  const btVector3 lo(btScalar(footprint.center.x() - ext.x() - grow - origin_.x()),
                     btScalar(footprint.center.y() - ext.y() - grow - origin_.y()), btScalar(-1.0));
  const btVector3 hi(btScalar(footprint.center.x() + ext.x() + grow - origin_.x()),
                     btScalar(footprint.center.y() + ext.y() + grow - origin_.y()),
                     btScalar(robot_.height_m + 1.0));
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
  candidates_.clear();
  collect.out = &candidates_;
  world_.getBroadphase()->aabbTest(lo, hi, collect);
  // Scenario order, as a loop over all of them would wake them (the order bodies are added in
  // is the order the solver sees them).
  std::sort(candidates_.begin(), candidates_.end());
  for (int index : candidates_) {
    const auto i = static_cast<std::size_t>(index);
    if (!blocksRobot(obstacles_[i], robot_)) continue;
    // The separating-axis gap is a lower bound of the true gap: it wakes early, never late.
    if (separationAlongAxes(footprint, obstacles_[i].box) < model_.parked_wake_distance_m) {
      wake(i);
      woken_.push_back(index);
    }
  }
}

}  // namespace parksim
