#include "parksim/sim/contacts/ChassisContacts.h"

#include <algorithm>

#include <BulletCollision/BroadphaseCollision/btDispatcher.h>
#include <BulletCollision/CollisionDispatch/btCollisionObject.h>
#include <BulletCollision/NarrowPhaseCollision/btPersistentManifold.h>

#include "parksim/sim/contacts/CollisionGroups.h"

namespace parksim {

void collectChassisContacts(btDispatcher& dispatcher, const btCollisionObject* chassis,
                            std::vector<int>& out) {
  out.clear();
  const int n = dispatcher.getNumManifolds();
  for (int i = 0; i < n; ++i) {
    const btPersistentManifold* m = dispatcher.getManifoldByIndexInternal(i);
    const btCollisionObject* other = nullptr;
    if (m->getBody0() == chassis) other = m->getBody1();
    if (m->getBody1() == chassis) other = m->getBody0();
    if (other == nullptr || other->getUserIndex() == kNotObstacle) continue;
    for (int p = 0; p < m->getNumContacts(); ++p) {
      if (m->getContactPoint(p).getDistance() < 0) {
        out.push_back(other->getUserIndex());
        break;
      }
    }
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
}

}  // namespace parksim
