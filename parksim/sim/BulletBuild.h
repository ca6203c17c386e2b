#pragma once
// Which Bullet this build links, for provenance in results tables (Bullet's own headers stay
// inside the sim module).

namespace parksim {

/// "float" or "double": the precision of Bullet's btScalar in this build.
const char* bulletPrecision();

/// Bullet's version as btGetVersion() reports it, e.g. 324 for 3.24.
int bulletVersion();

}  // namespace parksim
