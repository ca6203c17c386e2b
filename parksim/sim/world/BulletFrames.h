#pragma once
// Planar poses as Bullet transforms and back. Internal to sim/; Bullet's transform type is
// only declared here.

class btTransform;

namespace parksim {

/// A frame at (x, y, z) turned by `yaw` about +z (m, rad), in Bullet's float.
btTransform planarTransform(double x, double y, double z, double yaw);

/// The heading of a frame's x axis in the xy plane, rad.
double yawOf(const btTransform& transform);

}  // namespace parksim
