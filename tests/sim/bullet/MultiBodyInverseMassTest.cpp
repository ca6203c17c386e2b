// The multibody's response to impulses from a matrix kept per body
// (sim/bullet/MultiBodyInverseMass.h) against Bullet's articulated-body pass, at poses and wheel
// angles other than the one the matrix was taken at.

#include "parksim/sim/bullet/MultiBodyInverseMass.h"

#include <BulletCollision/CollisionShapes/btBoxShape.h>
#include <BulletCollision/CollisionShapes/btSphereShape.h>
#include <BulletDynamics/Featherstone/btMultiBody.h>
#include <BulletDynamics/Featherstone/btMultiBodyConstraint.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <random>
#include <vector>

namespace parksim {
namespace {

// parksim's robot as RobotBody builds it: a 200 g box base, two 20 g sphere wheels on revolute
// joints about the base's y axis (one with a geared rotor's larger axle inertia), a fixed 2 g
// sphere slider.
std::unique_ptr<btMultiBody> makeRobot() {
  btVector3 base_inertia;
  btBoxShape(btVector3(0.04f, 0.0425f, 0.024f)).calculateLocalInertia(0.2f, base_inertia);
  btVector3 wheel_inertia;
  btSphereShape(0.02f).calculateLocalInertia(0.02f, wheel_inertia);
  btVector3 geared = wheel_inertia;
  geared.setY(1e-5f);
  btVector3 slider_inertia;
  btSphereShape(0.008f).calculateLocalInertia(0.002f, slider_inertia);
  auto robot = std::make_unique<btMultiBody>(3, 0.2f, base_inertia, false, false);
  btMultiBody& body = *robot;
  const btQuaternion none(0, 0, 0, 1);
  const btVector3 zero(0, 0, 0);
  body.setupRevolute(0, 0.02f, wheel_inertia, -1, none, btVector3(0, 1, 0),
                     btVector3(0.03f, 0.0425f, -0.006f), zero, true);
  body.setupRevolute(1, 0.02f, geared, -1, none, btVector3(0, 1, 0),
                     btVector3(0.03f, -0.0425f, -0.006f), zero, true);
  body.setupFixed(2, 0.002f, slider_inertia, -1, none, btVector3(-0.03f, 0, -0.018f), zero, true);
  body.finalizeMultiDof();
  return robot;
}

void pose(btMultiBody& body, double yaw, double tilt, double left, double right) {
  btTransform t;
  t.setIdentity();
  t.setOrigin(btVector3(1.5f, -0.7f, 0.026f));
  btQuaternion q(btVector3(0, 0, 1), btScalar(yaw));
  q *= btQuaternion(btVector3(1, 0, 0), btScalar(tilt));
  t.setRotation(q);
  body.setBaseWorldTransform(t);
  body.setJointPos(0, btScalar(left));
  body.setJointPos(1, btScalar(right));
  btAlignedObjectArray<btScalar> r;
  btAlignedObjectArray<btVector3> v;
  btAlignedObjectArray<btMatrix3x3> m;
  // Bullet's articulated-body pass of a step: what calcAccelerationDeltasMultiDof then reads.
  body.computeAccelerationsArticulatedBodyAlgorithmMultiDof(1.0f / 240, r, v, m, false, false,
                                                            false);
}

TEST(MultiBodyInverseMass, RespondsAsBulletsArticulatedBodyPassAtEveryPose) {
  const std::unique_ptr<btMultiBody> robot = makeRobot();
  btMultiBody& body = *robot;
  const int n = body.getNumDofs() + 6;
  MultiBodyInverseMass inverse;
  EXPECT_FALSE(inverse.covers(&body));
  inverse.add(&body);
  EXPECT_TRUE(inverse.covers(&body));
  btMultiBodyJacobianData data;
  data.m_jacobians.resize(n);
  data.m_deltaVelocitiesUnitImpulse.resize(n);
  std::mt19937_64 rng(21);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  // The first call takes the matrix at yaw 0.3; then other headings, tilts and wheel angles.
  const double poses[][4] = {{0.3, 0.0, 0.0, 0.0},
                             {2.1, 0.0, 1.0, -4.0},
                             {-2.9, 0.01, 7.0, 0.5},
                             {0.9, -0.2, -3.0, 2.0},
                             {3.1, 0.05, 0.2, 0.2}};
  std::vector<btScalar> expected(static_cast<std::size_t>(n));
  btAlignedObjectArray<btScalar> r;
  btAlignedObjectArray<btVector3> v;
  double worst = 0.0;
  for (const auto& p : poses) {
    pose(body, p[0], p[1], p[2], p[3]);
    for (int trial = 0; trial < 20; ++trial) {
      for (int i = 0; i < n; ++i) data.m_jacobians[i] = btScalar(u(rng));
      body.calcAccelerationDeltasMultiDof(&data.m_jacobians[0], expected.data(), r, v);
      inverse.respond(body, 0, data);
      double scale = 0.0;
      for (const btScalar e : expected) scale = std::max(scale, std::abs(double(e)));
      for (int i = 0; i < n; ++i) {
        const double diff =
            std::abs(double(data.m_deltaVelocitiesUnitImpulse[i]) - double(expected[i]));
        worst = std::max(worst, diff / scale);
      }
    }
  }
  std::printf("largest difference from Bullet's pass: %.3g of the response\n", worst);
  EXPECT_LT(worst, 1e-5);  // float rounding of Bullet's pass and of the matrix taken from it
}

}  // namespace
}  // namespace parksim
