#include "parksim/sim/bullet/DiscreteMultiBodyWorld.h"

#include <BulletCollision/CollisionDispatch/btCollisionObject.h>
#include <BulletDynamics/Featherstone/btMultiBody.h>
#include <BulletDynamics/Featherstone/btMultiBodyConstraintSolver.h>
#include <BulletDynamics/Featherstone/btMultiBodyDynamicsWorld.h>
#include <BulletDynamics/Featherstone/btMultiBodyLinkCollider.h>

namespace parksim {

namespace {

class DiscreteMultiBodyWorld final : public btMultiBodyDynamicsWorld {
 public:
  using btMultiBodyDynamicsWorld::btMultiBodyDynamicsWorld;

 protected:
  // btMultiBodyDynamicsWorld::predictUnconstraintMotion: the rigid bodies' prediction, then
  // predictMultiBodyTransforms without the prediction itself (see the header).
  void predictUnconstraintMotion(btScalar timeStep) override {
    // What the skipped prediction feeds: continuous dispatch (time of impact) and a kinematic
    // base's velocity (btMultiBody::saveKinematicState reads its interpolated transform).
    // parksim uses neither; should it ever, Bullet's full step runs.
    if (getDispatchInfo().m_dispatchFunc != btDispatcherInfo::DISPATCH_DISCRETE ||
        anyKinematicBase()) {
      btMultiBodyDynamicsWorld::predictUnconstraintMotion(timeStep);
      return;
    }
    btDiscreteDynamicsWorld::predictUnconstraintMotion(timeStep);
    for (int b = 0; b < m_multiBodies.size(); b++) {
      btMultiBody* body = m_multiBodies[b];
      if (sleeping(*body)) body->clearVelocities();
    }
  }

 private:
  bool anyKinematicBase() const {
    for (int b = 0; b < m_multiBodies.size(); b++) {
      if (m_multiBodies[b]->isBaseKinematic()) return true;
    }
    return false;
  }

  // Bullet's test in predictMultiBodyTransforms: the base's or any link's collider asleep.
  static bool sleeping(const btMultiBody& body) {
    bool asleep = body.getBaseCollider() != nullptr &&
                  body.getBaseCollider()->getActivationState() == ISLAND_SLEEPING;
    for (int l = 0; l < body.getNumLinks(); l++) {
      const btMultiBodyLinkCollider* collider = body.getLink(l).m_collider;
      if (collider != nullptr && collider->getActivationState() == ISLAND_SLEEPING) asleep = true;
    }
    return asleep;
  }
};

}  // namespace

std::unique_ptr<btMultiBodyDynamicsWorld> makeDiscreteMultiBodyWorld(
    btDispatcher* dispatcher, btBroadphaseInterface* broadphase,
    btMultiBodyConstraintSolver* solver, btCollisionConfiguration* config) {
  return std::make_unique<DiscreteMultiBodyWorld>(dispatcher, broadphase, solver, config);
}

}  // namespace parksim
