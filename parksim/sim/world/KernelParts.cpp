#include "parksim/sim/world/KernelParts.h"

#include <algorithm>
#include <memory>
#include <optional>

#include <BulletCollision/CollisionDispatch/btCollisionDispatcher.h>
#include <BulletDynamics/Featherstone/btMultiBody.h>
#include <BulletDynamics/Featherstone/btMultiBodyConstraintSolver.h>
#include <BulletDynamics/Featherstone/btMultiBodyDynamicsWorld.h>
#include <BulletDynamics/Featherstone/btMultiBodyJointMotor.h>

#include "parksim/sim/contacts/SphereBoxContacts.h"

// Set by parksim/sim/CMakeLists.txt (cmake/BulletSolver.cmake): 1 against Bullet 3.24 unless
// PARKSIM_BULLET_FAST_SOLVER is off.
#if PARKSIM_BULLET_TRANSCRIPTION
#include "parksim/sim/bullet/DiscreteMultiBodyWorld.h"
#include "parksim/sim/bullet/FastMultiBodySolver.h"
#include "parksim/sim/bullet/MultiBodyInverseMass.h"
#include "parksim/sim/bullet/WheelMotor.h"
#endif

namespace parksim {

SolverKernel effectiveSolverKernel(SolverKernel requested) {
#if PARKSIM_BULLET_TRANSCRIPTION
  return requested;
#else
  (void)requested;
  return SolverKernel::kBullet;
#endif
}

struct KernelParts::Impl {
  SolverKernel kernel = SolverKernel::kBullet;
  int min_iterations = 0;
  std::optional<SphereBoxContacts> sphere_box;  // registered with the dispatcher
#if PARKSIM_BULLET_TRANSCRIPTION
  MultiBodyInverseMass inverse_mass;  // outlives the solver and the motors
#endif
  std::unique_ptr<btMultiBodyConstraintSolver> solver;
};

KernelParts::KernelParts(const SimModelDef& model, btCollisionDispatcher& dispatcher,
                         bool warm_start_friction)
    : impl_(std::make_unique<Impl>()) {
  Impl& d = *impl_;
  d.kernel = effectiveSolverKernel(model.solver);
  if (d.kernel != model.solver && model.warm_start) d.min_iterations = model.cold_solver_iterations;
  if (d.kernel == SolverKernel::kBullet) {
    d.solver = std::make_unique<btMultiBodyConstraintSolver>();
    return;
  }
#if PARKSIM_BULLET_TRANSCRIPTION
  if (d.kernel == SolverKernel::kFast) d.sphere_box.emplace(dispatcher);
  FastSolverDef fast;
  fast.pairwise_dots = d.kernel == SolverKernel::kFast;
  fast.warm_start = model.warm_start;
  fast.warm_start_friction = warm_start_friction;
  // kFast sets the robot's rows up from its constant mass matrix (rounding differs from
  // Bullet's); kExact keeps Bullet's setup, bit for bit.
  if (d.kernel == SolverKernel::kFast) fast.inverse_mass = &d.inverse_mass;
  d.solver = makeFastMultiBodySolver(fast);
#else
  (void)dispatcher;
  (void)warm_start_friction;
#endif
}

KernelParts::~KernelParts() = default;

SolverKernel KernelParts::kernel() const { return impl_->kernel; }

int KernelParts::solverIterations(int iterations) const {
  return std::max(iterations, impl_->min_iterations);
}

std::unique_ptr<btMultiBodyDynamicsWorld> KernelParts::makeWorld(btCollisionDispatcher& dispatcher,
                                                                 btBroadphaseInterface& broadphase,
                                                                 btCollisionConfiguration& config) {
  // Bullet's kernel is the reference in Bullet's own world, so the kernels' bit-identity test
  // (SolverPathsTest) covers the discrete world's skipped prediction too.
#if PARKSIM_BULLET_TRANSCRIPTION
  if (impl_->kernel != SolverKernel::kBullet) {
    return makeDiscreteMultiBodyWorld(&dispatcher, &broadphase, impl_->solver.get(), &config);
  }
#endif
  return std::make_unique<btMultiBodyDynamicsWorld>(&dispatcher, &broadphase, impl_->solver.get(),
                                                    &config);
}

void KernelParts::addRobot(const btMultiBody& robot) {
#if PARKSIM_BULLET_TRANSCRIPTION
  if (impl_->kernel == SolverKernel::kFast) impl_->inverse_mass.add(&robot);
#else
  (void)robot;
#endif
}

std::unique_ptr<btMultiBodyJointMotor> KernelParts::makeWheelMotor(btMultiBody& body, int link,
                                                                   double max_impulse) {
#if PARKSIM_BULLET_TRANSCRIPTION
  if (impl_->inverse_mass.covers(&body)) {
    return parksim::makeWheelMotor(body, link, max_impulse, impl_->inverse_mass);
  }
#endif
  return std::make_unique<btMultiBodyJointMotor>(&body, link, btScalar(0), btScalar(max_impulse));
}

}  // namespace parksim
