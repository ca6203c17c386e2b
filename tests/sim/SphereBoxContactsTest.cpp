// Sphere-box contacts (sim/contacts/SphereBoxContacts.h): the point, normal and distance Bullet's
// manifold receives are the exact closest point of the box, the way a wheel rests on the ground.

#include "parksim/sim/contacts/SphereBoxContacts.h"

#include <btBulletCollisionCommon.h>
#include <gtest/gtest.h>

#include <cmath>

namespace parksim {
namespace {

struct Scene {
  btDefaultCollisionConfiguration config;
  btCollisionDispatcher dispatcher{&config};
  SphereBoxContacts contacts{dispatcher};
  btDbvtBroadphase broadphase;
  btCollisionWorld world{&dispatcher, &broadphase, &config};
  btBoxShape ground_shape{btVector3(2.0f, 1.5f, 0.05f)};  // Bullet's margin: 5 mm, inside
  btSphereShape wheel_shape{0.02f};
  btCollisionObject ground;
  btCollisionObject wheel;

  explicit Scene(const btVector3& wheel_centre) {
    btTransform t;
    t.setIdentity();
    t.setOrigin(btVector3(0.9f, 0.6f, -0.05f));  // top face at z = 0
    ground.setWorldTransform(t);
    ground.setCollisionShape(&ground_shape);
    t.setOrigin(wheel_centre);
    wheel.setWorldTransform(t);
    wheel.setCollisionShape(&wheel_shape);
    world.addCollisionObject(&ground);
    world.addCollisionObject(&wheel);
    world.performDiscreteCollisionDetection();
  }
  ~Scene() {
    world.removeCollisionObject(&wheel);
    world.removeCollisionObject(&ground);
  }

  // The manifold's one point: the ground's normal there (pointing to the wheel) and the point
  // on the ground.
  const btManifoldPoint* point(btVector3& normal_up, btVector3* on_ground = nullptr) {
    if (dispatcher.getNumManifolds() != 1) return nullptr;
    const btPersistentManifold* m = dispatcher.getManifoldByIndexInternal(0);
    if (m->getNumContacts() != 1) return nullptr;
    const btManifoldPoint& p = m->getContactPoint(0);
    const bool wheel_first = m->getBody0() == &wheel;
    normal_up = wheel_first ? p.m_normalWorldOnB : -p.m_normalWorldOnB;
    if (on_ground != nullptr)
      *on_ground = wheel_first ? p.getPositionWorldOnB() : p.getPositionWorldOnA();
    return &p;
  }
};

TEST(SphereBoxContacts, AWheelOnTheGroundTouchesStraightBelowItsCentre) {
  for (const float height : {0.0199f, 0.02f, 0.0203f}) {
    Scene scene(btVector3(1.234f, 0.567f, height));
    btVector3 up;
    btVector3 on_ground;
    const btManifoldPoint* p = scene.point(up, &on_ground);
    ASSERT_NE(p, nullptr) << height;
    EXPECT_NEAR(p->getDistance(), height - 0.02f, 1e-7) << height;
    EXPECT_NEAR(up.z(), 1.0f, 1e-7);
    EXPECT_NEAR(on_ground.x(), 1.234f, 1e-6);
    EXPECT_NEAR(on_ground.y(), 0.567f, 1e-6);
    EXPECT_NEAR(on_ground.z(), 0.0f, 1e-7);
  }
}

TEST(SphereBoxContacts, FarAwayThereIsNoContactAndAtAnEdgeTheNormalLeansOut) {
  {
    Scene far(btVector3(1.0f, 0.6f, 0.5f));
    btVector3 up;
    EXPECT_EQ(far.point(up), nullptr);
  }
  // Beyond the slab's +x edge (x = 2.9), level with its top: the nearest point is on the rounded
  // edge, the normal between +x and +z.
  Scene edge(btVector3(2.9f + 0.01f, 0.6f, 0.01f));
  btVector3 up;
  const btManifoldPoint* p = edge.point(up);
  ASSERT_NE(p, nullptr);
  EXPECT_GT(up.x(), 0.5f);
  EXPECT_GT(up.z(), 0.5f);
}

TEST(SphereBoxContacts, ASphereSunkIntoTheBoxIsPushedOutThroughTheNearestFace) {
  // Centre 1 cm below the top face, far from the sides: out through the top, 3 cm deep.
  Scene sunk(btVector3(0.9f, 0.6f, -0.01f));
  btVector3 up;
  const btManifoldPoint* p = sunk.point(up);
  ASSERT_NE(p, nullptr);
  EXPECT_NEAR(up.z(), 1.0f, 1e-6);
  EXPECT_NEAR(p->getDistance(), -0.03f, 1e-6);
}

}  // namespace
}  // namespace parksim
