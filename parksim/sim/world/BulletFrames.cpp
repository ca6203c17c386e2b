#include "parksim/sim/world/BulletFrames.h"

#include <cmath>

#include <LinearMath/btTransform.h>

namespace parksim {

btTransform planarTransform(double x, double y, double z, double yaw) {
  btTransform tr;
  tr.setIdentity();
  tr.setOrigin(btVector3(btScalar(x), btScalar(y), btScalar(z)));
  tr.setRotation(btQuaternion(btVector3(0, 0, 1), btScalar(yaw)));
  return tr;
}

double yawOf(const btTransform& transform) {
  const btMatrix3x3& r = transform.getBasis();
  return std::atan2(double(r[1][0]), double(r[0][0]));
}

}  // namespace parksim
