#include "parksim/sim/BulletBuild.h"

#include <LinearMath/btScalar.h>

namespace parksim {

const char* bulletPrecision() { return sizeof(btScalar) == sizeof(double) ? "double" : "float"; }

int bulletVersion() { return btGetVersion(); }

}  // namespace parksim
