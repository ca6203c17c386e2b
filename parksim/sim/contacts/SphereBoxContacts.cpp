#include "parksim/sim/contacts/SphereBoxContacts.h"

#include <BulletCollision/BroadphaseCollision/btBroadphaseProxy.h>
#include <BulletCollision/CollisionDispatch/btActivatingCollisionAlgorithm.h>
#include <BulletCollision/CollisionDispatch/btCollisionCreateFunc.h>
#include <BulletCollision/CollisionDispatch/btCollisionDispatcher.h>
#include <BulletCollision/CollisionDispatch/btCollisionObjectWrapper.h>
#include <BulletCollision/CollisionDispatch/btManifoldResult.h>
#include <BulletCollision/CollisionShapes/btBoxShape.h>
#include <BulletCollision/CollisionShapes/btSphereShape.h>
#include <BulletCollision/NarrowPhaseCollision/btPersistentManifold.h>

namespace parksim {

namespace {

// The point of a box (a core of half extents `half`, grown by `margin`) nearest to a point
// `p` in the box's frame, the outward normal there, and the signed distance from the box to p.
struct Nearest {
  btVector3 point;
  btVector3 normal;
  btScalar distance;
};

Nearest nearestOnBox(const btVector3& half, btScalar margin, const btVector3& p) {
  btVector3 core = p;
  for (int i = 0; i < 3; ++i) core[i] = btMax(-half[i], btMin(half[i], p[i]));
  const btVector3 offset = p - core;
  const btScalar d2 = offset.length2();
  if (d2 > SIMD_EPSILON) {
    const btScalar d = btSqrt(d2);
    const btVector3 normal = offset / d;
    return {core + normal * margin, normal, d - margin};
  }
  // Inside the core: out through the face nearest to p.
  Nearest best{p, btVector3(1, 0, 0), -(half[0] - p[0]) - margin};
  btScalar depth = BT_LARGE_FLOAT;
  for (int i = 0; i < 3; ++i) {
    for (const btScalar side : {btScalar(1), btScalar(-1)}) {
      const btScalar face = half[i] - side * p[i];
      if (face >= depth) continue;
      depth = face;
      best.point = p;
      best.point[i] = side * (half[i] + margin);
      best.normal = btVector3(0, 0, 0);
      best.normal[i] = side;
      best.distance = -face - margin;
    }
  }
  return best;
}

class SphereBoxAlgorithm final : public btActivatingCollisionAlgorithm {
 public:
  SphereBoxAlgorithm(const btCollisionAlgorithmConstructionInfo& ci,
                     const btCollisionObjectWrapper* body0, const btCollisionObjectWrapper* body1,
                     bool swapped)
      : btActivatingCollisionAlgorithm(ci, body0, body1), swapped_(swapped) {
    const btCollisionObject* sphere = (swapped ? body1 : body0)->getCollisionObject();
    const btCollisionObject* box = (swapped ? body0 : body1)->getCollisionObject();
    if (m_dispatcher->needsCollision(sphere, box)) {
      manifold_ = m_dispatcher->getNewManifold(sphere, box);
    }
  }

  ~SphereBoxAlgorithm() override {
    if (manifold_ != nullptr) m_dispatcher->releaseManifold(manifold_);
  }

  void processCollision(const btCollisionObjectWrapper* body0,
                        const btCollisionObjectWrapper* body1, const btDispatcherInfo&,
                        btManifoldResult* result) override {
    if (manifold_ == nullptr) return;
    const btCollisionObjectWrapper* sphere_wrap = swapped_ ? body1 : body0;
    const btCollisionObjectWrapper* box_wrap = swapped_ ? body0 : body1;
    const auto* sphere = static_cast<const btSphereShape*>(sphere_wrap->getCollisionShape());
    const auto* box = static_cast<const btBoxShape*>(box_wrap->getCollisionShape());
    const btTransform& frame = box_wrap->getWorldTransform();
    result->setPersistentManifold(manifold_);
    const Nearest n = nearestOnBox(box->getHalfExtentsWithoutMargin(), box->getMargin(),
                                   frame.invXform(sphere_wrap->getWorldTransform().getOrigin()));
    // Points within the contact breaking threshold are kept, as Bullet's algorithms do.
    const btScalar depth = n.distance - sphere->getRadius();
    if (depth <= manifold_->getContactBreakingThreshold()) {
      result->addContactPoint(frame.getBasis() * n.normal, frame(n.point), depth);
    }
    if (manifold_->getNumContacts() != 0) result->refreshContactPoints();
  }

  btScalar calculateTimeOfImpact(btCollisionObject*, btCollisionObject*, const btDispatcherInfo&,
                                 btManifoldResult*) override {
    return btScalar(1);  // no continuous collision detection, as Bullet's own
  }

  void getAllContactManifolds(btManifoldArray& manifolds) override {
    if (manifold_ != nullptr) manifolds.push_back(manifold_);
  }

 private:
  btPersistentManifold* manifold_ = nullptr;
  bool swapped_;
};

struct CreateFunc final : btCollisionAlgorithmCreateFunc {
  explicit CreateFunc(bool swapped) { m_swapped = swapped; }
  btCollisionAlgorithm* CreateCollisionAlgorithm(btCollisionAlgorithmConstructionInfo& ci,
                                                 const btCollisionObjectWrapper* body0,
                                                 const btCollisionObjectWrapper* body1) override {
    void* memory = ci.m_dispatcher1->allocateCollisionAlgorithm(sizeof(SphereBoxAlgorithm));
    return new (memory) SphereBoxAlgorithm(ci, body0, body1, m_swapped);
  }
};

}  // namespace

struct SphereBoxContacts::Funcs {
  CreateFunc sphere_box{false};
  CreateFunc box_sphere{true};
};

SphereBoxContacts::SphereBoxContacts(btCollisionDispatcher& dispatcher)
    : funcs_(std::make_unique<Funcs>()) {
  dispatcher.registerCollisionCreateFunc(SPHERE_SHAPE_PROXYTYPE, BOX_SHAPE_PROXYTYPE,
                                         &funcs_->sphere_box);
  dispatcher.registerCollisionCreateFunc(BOX_SHAPE_PROXYTYPE, SPHERE_SHAPE_PROXYTYPE,
                                         &funcs_->box_sphere);
}

SphereBoxContacts::~SphereBoxContacts() = default;

}  // namespace parksim
