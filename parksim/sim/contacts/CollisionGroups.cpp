#include "parksim/sim/contacts/CollisionGroups.h"

#include <BulletCollision/BroadphaseCollision/btOverlappingPairCache.h>
#include <BulletCollision/CollisionDispatch/btCollisionObject.h>

namespace parksim {

namespace {

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

}  // namespace

std::unique_ptr<btOverlapFilterCallback> makeFixedObstaclePairFilter() {
  return std::make_unique<FixedObstaclePairFilter>();
}

}  // namespace parksim
