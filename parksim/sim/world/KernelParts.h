#pragma once
// What SimModelDef::solver decides in the dynamics world: the constraint solver, the world that
// steps it, the robot's wheel motors and its wheels' ground contacts. Every kernel but kBullet
// runs parksim's transcription of Bullet 3.24's solver (sim/bullet/, its README.md), which the
// build compiles only against Bullet 3.24 and with PARKSIM_BULLET_FAST_SOLVER on; without it
// every kernel is Bullet's own (effectiveSolverKernel). The one place that chooses between them.
// Internal to sim/; Bullet's types are only declared here.

#include <memory>

#include "parksim/sim/world/DynamicsWorld.h"

class btBroadphaseInterface;
class btCollisionConfiguration;
class btCollisionDispatcher;
class btMultiBody;
class btMultiBodyDynamicsWorld;
class btMultiBodyJointMotor;

namespace parksim {

class KernelParts {
 public:
  /// The parts of effectiveSolverKernel(model.solver) for a world of `dispatcher`, which must
  /// outlive them. `warm_start_friction`: whether the transcribed solver warm-starts friction
  /// rows too (FastSolverDef; false for a car).
  KernelParts(const SimModelDef& model, btCollisionDispatcher& dispatcher,
              bool warm_start_friction = true);
  ~KernelParts();

  KernelParts(const KernelParts&) = delete;
  KernelParts& operator=(const KernelParts&) = delete;

  /// The kernel these parts run.
  SolverKernel kernel() const;

  /// The most solver iterations per step for a world whose PhysicsDef asks for `iterations`:
  /// those, or SimModelDef::cold_solver_iterations if more where Bullet's own solver stands in
  /// for a warm-started kernel.
  int solverIterations(int iterations) const;

  /// The world that steps with this kernel's solver; it must not outlive these parts.
  std::unique_ptr<btMultiBodyDynamicsWorld> makeWorld(btCollisionDispatcher& dispatcher,
                                                      btBroadphaseInterface& broadphase,
                                                      btCollisionConfiguration& config);

  /// The ego robot, built, before its motors are made: kFast sets its contact and motor rows up
  /// from its mass matrix, which must be constant in its base frame (sphere wheels turning about
  /// their axles, fixed sliders: sim/bullet/MultiBodyInverseMass.h).
  void addRobot(const btMultiBody& robot);

  /// A velocity motor on revolute joint `link` of `body`, at most `max_impulse` (N m s) per step,
  /// target 0. It must not outlive these parts.
  std::unique_ptr<btMultiBodyJointMotor> makeWheelMotor(btMultiBody& body, int link,
                                                        double max_impulse);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace parksim
