#pragma once
// The velocity response of a multibody to an impulse, M^-1 J^T, from a matrix kept per body
// instead of Bullet's articulated-body pass for every constraint row. Internal to sim/; Bullet's
// types are only declared here.
//
// Bullet sets up each contact and motor row of a multibody with calcAccelerationDeltasMultiDof,
// an articulated-body pass over the whole tree (3-6k instructions per row, ~11 rows per step for
// the robot: 30 % of a step). For a multibody whose mass matrix, expressed in its base frame,
// never changes, M^-1 in Bullet's coordinates (base angular and linear velocity in the world
// frame, then the joint velocities) is that constant matrix turned by the base's rotation:
// M^-1 = T^T L T with T = diag(R, R, 1), R the world-to-base rotation. L is taken from Bullet
// itself, once per body (its response to unit impulses at the first use), and every row then
// costs a few rotations and an n x n product in double. Results agree with Bullet's pass to
// float rounding (tested: MultiBodyInverseMassTest).
//
// The mass matrix is constant in the base frame when every moving link turns about an axis of
// symmetry of its inertia with its centre of mass on that axis, as parksim's robot's wheels do
// (spheres on their axles; the slider is a fixed link).

#include <vector>

class btMultiBody;
struct btMultiBodyJacobianData;

namespace parksim {

class MultiBodyInverseMass {
 public:
  /// `body` meets the condition above; its rows are set up here from now on.
  void add(const btMultiBody* body);
  bool covers(const btMultiBody* body) const;

  /// data.m_deltaVelocitiesUnitImpulse[index ...] = M^-1 data.m_jacobians[index ...] for
  /// `body` (6 + its dofs entries each). At the first call for a body Bullet's own response to
  /// unit impulses gives L: call it after Bullet's articulated-body pass of the step (during the
  /// constraint solver's setup, as Bullet's own rows are computed).
  void respond(btMultiBody& body, int index, btMultiBodyJacobianData& data);

 private:
  struct Body {
    const btMultiBody* body = nullptr;
    int n = 0;                  // 6 + dofs
    std::vector<double> local;  // L, n x n, column-major; empty until first use
    // The world-to-base rotation of the last call, and the quaternion it came from: the rows
    // of one step share it.
    double quaternion[4] = {0.0, 0.0, 0.0, 0.0};
    double rotation[3][3] = {};
    bool finite = false;  // every entry of L is finite
  };
  // The size of parksim's robot (6 + two wheels): its products are unrolled.
  static constexpr int kFixedSize = 8;

  Body* find(const btMultiBody* body);
  static void measure(btMultiBody& body, Body& entry, btMultiBodyJacobianData& data);

  std::vector<Body> bodies_;
  Body* last_ = nullptr;  // the body of the last call: rows come body by body
  std::vector<double> scratch_;
};

}  // namespace parksim
