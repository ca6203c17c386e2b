#pragma once
// Which obstacles the ego robot's chassis penetrates after a step, read from the contact
// manifolds the step left. Internal to sim/; Bullet's types are only declared here.

#include <vector>

class btCollisionObject;
class btDispatcher;

namespace parksim {

/// Replaces `out` with the user indices (scenario order, ascending, each once) of the obstacles
/// that have a contact point at negative distance with `chassis`. Touching within Bullet's
/// contact threshold without overlap does not count; objects with user index kNotObstacle
/// (CollisionGroups.h) are left out.
void collectChassisContacts(btDispatcher& dispatcher, const btCollisionObject* chassis,
                            std::vector<int>& out);

}  // namespace parksim
