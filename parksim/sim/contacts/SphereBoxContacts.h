#pragma once
// Contact points between spheres and boxes (the wheels and the slider on the ground slab) from
// the closest point on the box, instead of Bullet's general convex algorithm (GJK), which took
// 15k of the robot's ~80k instructions per step and finds the same point to within its
// tolerance. Internal to sim/; Bullet's types are only declared here.
//
// Bullet ships a sphere-box algorithm but leaves it unregistered (USE_BUGGY_SPHERE_BOX_ALGORITHM:
// its deep-penetration case sets a wrong point). This one is the same closest-point test
// with that case written out: a sphere whose centre lies inside the box is pushed out through
// the nearest face.

#include <memory>

class btCollisionDispatcher;

namespace parksim {

class SphereBoxContacts {
 public:
  /// Registers the algorithm with `dispatcher` for sphere-box pairs in either order. Must
  /// outlive every collision that `dispatcher` processes.
  explicit SphereBoxContacts(btCollisionDispatcher& dispatcher);
  ~SphereBoxContacts();

  SphereBoxContacts(const SphereBoxContacts&) = delete;
  SphereBoxContacts& operator=(const SphereBoxContacts&) = delete;

 private:
  struct Funcs;
  std::unique_ptr<Funcs> funcs_;
};

}  // namespace parksim
