// The colliders of the ego robot's links, alike for both bodies (EgoBody.h).

#include <BulletDynamics/Featherstone/btMultiBody.h>
#include <BulletDynamics/Featherstone/btMultiBodyDynamicsWorld.h>
#include <BulletDynamics/Featherstone/btMultiBodyLinkCollider.h>

#include "parksim/sim/contacts/CollisionGroups.h"
#include "parksim/sim/world/EgoBody.h"

namespace parksim {

void addEgoCollider(btMultiBodyDynamicsWorld& world, btMultiBody& body, int link,
                    btCollisionShape* shape, double friction, int group, int mask,
                    double wheel_contact_processing_m,
                    std::vector<std::unique_ptr<btMultiBodyLinkCollider>>& colliders) {
  auto collider = std::make_unique<btMultiBodyLinkCollider>(&body, link);
  collider->setCollisionShape(shape);
  collider->setFriction(btScalar(friction));
  collider->setUserIndex(kNotObstacle);
  if (link >= 0) collider->setContactProcessingThreshold(btScalar(wheel_contact_processing_m));
  world.addCollisionObject(collider.get(), group, mask);
  if (link < 0) {
    body.setBaseCollider(collider.get());
  } else {
    body.getLink(link).m_collider = collider.get();
  }
  colliders.push_back(std::move(collider));
}

}  // namespace parksim
