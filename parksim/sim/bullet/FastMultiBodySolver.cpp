#include "parksim/sim/bullet/FastMultiBodySolver.h"

#include <cmath>
#include <cstddef>
#include <vector>

#include <BulletCollision/NarrowPhaseCollision/btPersistentManifold.h>
#include <BulletDynamics/ConstraintSolver/btSolverBody.h>
#include <BulletDynamics/Featherstone/btMultiBody.h>
#include <BulletDynamics/Featherstone/btMultiBodyConstraintSolver.h>
#include <BulletDynamics/Featherstone/btMultiBodyLinkCollider.h>
#include <BulletDynamics/Featherstone/btMultiBodySolverConstraint.h>

#include "parksim/sim/bullet/MultiBodyContactRows.h"
#include "parksim/sim/bullet/SolverWarmStart.h"

// Every file of this folder reads Bullet's internals as 3.24 has them (README.md); the build
// compiles them against 3.24 only (cmake/BulletSolver.cmake), and this says so if it did not.
static_assert(BT_BULLET_VERSION == 324, "parksim/sim/bullet/ transcribes Bullet 3.24");

namespace parksim {

namespace {

// A transcription of btMultiBodyConstraintSolver::solveSingleIteration and the two row
// solvers it calls (Bullet 3.24, src/BulletDynamics/Featherstone/btMultiBodyConstraintSolver.cpp)
// for DIRECTLY_UPDATE_VELOCITY_DURING_SOLVER_ITERATIONS (set in Bullet's header). Every float
// operation is Bullet's, in Bullet's order: the dot products accumulate sequentially from
// zero, and nothing here may be reassociated (no -ffast-math). What differs is only how the
// work is dispatched: the rows are solved inline, a row of the robot against a fixed body
// reads its arrays from pointers resolved once per step and leaves out the fixed side's terms,
// which provably change nothing (see Row), and a frictionless contact's friction pair is
// skipped (see solveConePair).
class FastMultiBodySolver final : public btMultiBodyConstraintSolver {
 public:
  explicit FastMultiBodySolver(const FastSolverDef& def)
      : def_(def), warm_start_(def.warm_start_friction) {}

 protected:
  // Bullet's setup, then the rows as the iterations take them (resolveRows), with the one
  // non-zero Jacobian entry of each non-contact row (a joint motor acts on its own joint's
  // velocity only).
  btScalar solveGroupCacheFriendlySetup(btCollisionObject** bodies, int numBodies,
                                        btPersistentManifold** manifoldPtr, int numManifolds,
                                        btTypedConstraint** constraints, int numConstraints,
                                        const btContactSolverInfo& infoGlobal,
                                        btIDebugDraw* debugDrawer) override {
    const btScalar result = btMultiBodyConstraintSolver::solveGroupCacheFriendlySetup(
        bodies, numBodies, manifoldPtr, numManifolds, constraints, numConstraints, infoGlobal,
        debugDrawer);
    if (warmStarting(infoGlobal)) {
      warm_start_.apply(m_multiBodyNormalContactConstraints, m_multiBodyFrictionContactConstraints,
                        m_multiBodyNonContactConstraints, m_data, m_tmpSolverBodyPool);
    }
    resolveRows(m_multiBodyNonContactConstraints, non_contact_rows_, true);
    resolveRows(m_multiBodyNormalContactConstraints, normal_rows_, false);
    resolveRows(m_multiBodyFrictionContactConstraints, friction_rows_, false);
    return result;
  }

  btScalar solveSingleIteration(int iteration, btCollisionObject** bodies, int numBodies,
                                btPersistentManifold** manifoldPtr, int numManifolds,
                                btTypedConstraint** constraints, int numConstraints,
                                const btContactSolverInfo& infoGlobal,
                                btIDebugDraw* debugDrawer) override {
    // Bullet's rigid-body part: with no rigid-body rows and no typed constraints it loops over
    // empty pools and returns 0 (and draws no random numbers: there is nothing to shuffle).
    btScalar leastSquaredResidual = 0.f;
    if (numConstraints != 0 || m_tmpSolverNonContactConstraintPool.size() != 0 ||
        m_tmpSolverContactConstraintPool.size() != 0 ||
        m_tmpSolverContactFrictionConstraintPool.size() != 0 ||
        m_tmpSolverContactRollingFrictionConstraintPool.size() != 0) {
      leastSquaredResidual = btSequentialImpulseConstraintSolver::solveSingleIteration(
          iteration, bodies, numBodies, manifoldPtr, numManifolds, constraints, numConstraints,
          infoGlobal, debugDrawer);
    }
    return def_.pairwise_dots ? iterate<true>(iteration, infoGlobal, leastSquaredResidual)
                              : iterate<false>(iteration, infoGlobal, leastSquaredResidual);
  }

  template <bool kPairwise>
  btScalar iterate(int iteration, const btContactSolverInfo& infoGlobal,
                   btScalar leastSquaredResidual) {
    btScalar nonContactResidual = 0;
    const int n = static_cast<int>(non_contact_rows_.size());
    for (int i = 0; i < infoGlobal.m_numNonContactInnerIterations; ++i) {
      nonContactResidual = 0;
      for (int j = 0; j < n; j++) {
        const int index = iteration & 1 ? j : n - 1 - j;
        const Row& row = non_contact_rows_[std::size_t(index)];
        const btScalar residual = solve<kPairwise>(row);
        nonContactResidual = btMax(nonContactResidual, residual * residual);
        markMoved(row);
      }
    }
    leastSquaredResidual = btMax(leastSquaredResidual, nonContactResidual);

    for (const Row& row : normal_rows_) {
      btScalar residual = 0.f;
      if (iteration < infoGlobal.m_numIterations) residual = solve<kPairwise>(row);
      leastSquaredResidual = btMax(leastSquaredResidual, residual * residual);
      markMoved(row);
    }

    const bool cone = (infoGlobal.m_solverMode & SOLVER_USE_2_FRICTION_DIRECTIONS) &&
                      (infoGlobal.m_solverMode & SOLVER_DISABLE_IMPLICIT_CONE_FRICTION) == 0;
    if (!cone) {
      if (iteration >= infoGlobal.m_numIterations) return leastSquaredResidual;
      for (const Row& row : friction_rows_) {
        btMultiBodySolverConstraint& frictionConstraint = *row.c;
        const btScalar totalImpulse =
            m_multiBodyNormalContactConstraints[frictionConstraint.m_frictionIndex]
                .m_appliedImpulse;
        if (totalImpulse > btScalar(0)) {
          setLimits(frictionConstraint, totalImpulse);
          const btScalar residual = solve<kPairwise>(row);
          leastSquaredResidual = btMax(leastSquaredResidual, residual * residual);
          markMoved(row);
        }
      }
      return leastSquaredResidual;
    }
    if (iteration >= infoGlobal.m_numIterations) return leastSquaredResidual;

    // Spinning and torsional friction exist only with rolling or spinning friction, which
    // parksim does not use; they keep Bullet's own row solvers.
    for (int j1 = 0; j1 < m_multiBodySpinningFrictionContactConstraints.size(); j1++) {
      btMultiBodySolverConstraint& frictionConstraint =
          m_multiBodySpinningFrictionContactConstraints[j1];
      const btScalar totalImpulse =
          m_multiBodyNormalContactConstraints[frictionConstraint.m_frictionIndex].m_appliedImpulse;
      if (totalImpulse > btScalar(0)) {
        frictionConstraint.m_lowerLimit = -(frictionConstraint.m_friction * totalImpulse);
        frictionConstraint.m_upperLimit = frictionConstraint.m_friction * totalImpulse;
        const btScalar residual = resolveSingleConstraintRowGeneric(frictionConstraint);
        leastSquaredResidual = btMax(leastSquaredResidual, residual * residual);
        markMoved(frictionConstraint);
      }
    }
    for (int j1 = 0; j1 < m_multiBodyTorsionalFrictionContactConstraints.size(); j1++) {
      btMultiBodySolverConstraint& frictionConstraint =
          m_multiBodyTorsionalFrictionContactConstraints[j1];
      const btScalar totalImpulse =
          m_multiBodyNormalContactConstraints[frictionConstraint.m_frictionIndex].m_appliedImpulse;
      j1++;
      btMultiBodySolverConstraint& frictionConstraintB =
          m_multiBodyTorsionalFrictionContactConstraints[j1];
      if (totalImpulse > btScalar(0) &&
          frictionConstraint.m_frictionIndex == frictionConstraintB.m_frictionIndex) {
        setLimits(frictionConstraint, totalImpulse);
        setLimits(frictionConstraintB, totalImpulse);
        const btScalar residual =
            resolveConeFrictionConstraintRows(frictionConstraint, frictionConstraintB);
        leastSquaredResidual = btMax(leastSquaredResidual, residual * residual);
        markMoved(frictionConstraint);
        markMoved(frictionConstraintB);
      }
    }

    const std::size_t pairs = friction_rows_.size();
    for (std::size_t j1 = 0; j1 < pairs; j1 += 2) {
      const Row& rowA = friction_rows_[j1];
      btMultiBodySolverConstraint& frictionConstraint = *rowA.c;
      const btScalar totalImpulse =
          m_multiBodyNormalContactConstraints[frictionConstraint.m_frictionIndex].m_appliedImpulse;
      const Row& rowB = friction_rows_[j1 + 1];
      btMultiBodySolverConstraint& frictionConstraintB = *rowB.c;
      if (frictionConstraint.m_frictionIndex == frictionConstraintB.m_frictionIndex) {
        setLimits(frictionConstraint, totalImpulse);
        setLimits(frictionConstraintB, totalImpulse);
        const btScalar residual = solveConePair<kPairwise>(rowA, rowB);
        leastSquaredResidual = btMax(leastSquaredResidual, residual * residual);
        markMoved(rowB);
        markMoved(rowA);
      }
    }
    return leastSquaredResidual;
  }

  // Bullet's convertContacts (3.24), with the rows of a covered multibody against a fixed object
  // set up from the inverse mass (MultiBodyContactRows.h). Bullet's own articulated warm start
  // is never on here (warmStarting() and addFixedContactRows refuse it): every non-contact row
  // starts at zero, as Bullet's do without it.
  void convertContacts(btPersistentManifold** manifoldPtr, int numManifolds,
                       const btContactSolverInfo& infoGlobal) override {
    if (def_.inverse_mass == nullptr ||
        (infoGlobal.m_solverMode & SOLVER_USE_ARTICULATED_WARMSTARTING) != 0) {
      btMultiBodyConstraintSolver::convertContacts(manifoldPtr, numManifolds, infoGlobal);
      return;
    }
    ContactRowTarget target{m_multiBodyNormalContactConstraints,
                            m_multiBodyFrictionContactConstraints, m_data, m_tmpSolverBodyPool,
                            *def_.inverse_mass};
    for (int i = 0; i < numManifolds; i++) {
      btPersistentManifold* manifold = manifoldPtr[i];
      auto* body0 = const_cast<btCollisionObject*>(manifold->getBody0());
      auto* body1 = const_cast<btCollisionObject*>(manifold->getBody1());
      const bool link0 = btMultiBodyLinkCollider::upcast(body0) != nullptr;
      const bool link1 = btMultiBodyLinkCollider::upcast(body1) != nullptr;
      if (!link0 && !link1) {
        convertContact(manifold, infoGlobal);
        continue;
      }
      // As convertMultiBodyContact asks for them, A first.
      const int a = link0 ? -1 : getOrInitSolverBody(*body0, infoGlobal.m_timeStep);
      const int b = link1 ? -1 : getOrInitSolverBody(*body1, infoGlobal.m_timeStep);
      if (!addFixedContactRows(*manifold, a, b, infoGlobal, target)) {
        convertMultiBodyContact(manifold, infoGlobal);
      }
    }
    for (int i = 0; i < m_tmpNumMultiBodyConstraints; i++) {
      m_data.m_solverBodyPool = &m_tmpSolverBodyPool;
      m_data.m_fixedBodyId = m_fixedBodyId;
      m_tmpMultiBodyConstraints[i]->createConstraintRows(m_multiBodyNonContactConstraints, m_data,
                                                         infoGlobal);
    }
    for (int i = 0; i < m_multiBodyNonContactConstraints.size(); i++) {
      m_multiBodyNonContactConstraints[i].m_appliedImpulse = 0;
    }
  }

  // Remembers the impulses for the next step's warm start, then Bullet's write-back.
  btScalar solveGroupCacheFriendlyFinish(btCollisionObject** bodies, int numBodies,
                                         const btContactSolverInfo& infoGlobal) override {
    if (warmStarting(infoGlobal)) {
      warm_start_.record(m_multiBodyNormalContactConstraints, m_multiBodyFrictionContactConstraints,
                         m_tmpSolverBodyPool);
    }
    return btMultiBodyConstraintSolver::solveGroupCacheFriendlyFinish(bodies, numBodies,
                                                                      infoGlobal);
  }

 private:
  // SolverWarmStart needs two friction rows per contact (2 friction directions), and must not
  // run on top of Bullet's own articulated warm start (impulses would be applied twice).
  bool warmStarting(const btContactSolverInfo& info) const {
    return def_.warm_start && (info.m_solverMode & SOLVER_USE_2_FRICTION_DIRECTIONS) != 0 &&
           (info.m_solverMode & SOLVER_USE_ARTICULATED_WARMSTARTING) == 0;
  }

  // Velocity components of the ego robot: 6 for the free base, one per wheel joint (the
  // slider's link is fixed). Other sizes take the general loops.
  static constexpr int kRobotDofs = 8;

  // A row as the iterations take it. `jac` not null: a row of one multibody of kRobotDofs
  // velocities against a fixed body or nothing, its arrays resolved once per step. The fixed
  // side adds nothing to such a row while the step's values are finite: a fixed body's
  // velocity change stays +0 (its inverse mass is 0, so what any of Bullet's row solvers applies
  // to it is +0 for a finite impulse), its dot product with the row's finite fixed-side terms is
  // +0, and subtracting +0 x m_jacDiagABInv (finite, >= 0, checked) leaves every value as it
  // was, -0 included. A non-finite contact normal or velocity (a state already lost) is not
  // checked for: there the two paths may give different NaNs.
  struct Row {
    btMultiBodySolverConstraint* c = nullptr;
    const btScalar* jac = nullptr;   // the multibody's Jacobian
    const btScalar* unit = nullptr;  // its response to a unit impulse
    btScalar* vel = nullptr;         // the solver's accumulated velocity change
    btScalar* body_vel = nullptr;    // the multibody's own (see applyToMultiBody)
    btMultiBody* body = nullptr;
    int single = -1;  // the only non-zero Jacobian entry on side A (non-contact rows), or -1
  };

  FastSolverDef def_;
  SolverWarmStart warm_start_;
  std::vector<Row> non_contact_rows_;
  std::vector<Row> normal_rows_;
  std::vector<Row> friction_rows_;

  // The rows of this step, after the setup has sized every array they point into.
  void resolveRows(btAlignedObjectArray<btMultiBodySolverConstraint>& constraints,
                   std::vector<Row>& rows, bool non_contact) {
    rows.resize(static_cast<std::size_t>(constraints.size()));
    for (int j = 0; j < constraints.size(); ++j) {
      btMultiBodySolverConstraint& c = constraints[j];
      Row& row = rows[static_cast<std::size_t>(j)];
      row = Row{};
      row.c = &c;
      if (non_contact) row.single = singleNonZero(c);
      const bool on_a = c.m_multiBodyA != nullptr && c.m_multiBodyB == nullptr;
      const bool on_b = c.m_multiBodyB != nullptr && c.m_multiBodyA == nullptr;
      if (!on_a && !on_b) continue;
      btMultiBody* body = on_a ? c.m_multiBodyA : c.m_multiBodyB;
      const int other = on_a ? c.m_solverBodyIdB : c.m_solverBodyIdA;
      const bool fixed_other = other < 0 || m_tmpSolverBodyPool[other].m_originalBody == nullptr;
      if (body->getNumDofs() + 6 != kRobotDofs || !fixed_other ||
          !(c.m_jacDiagABInv >= btScalar(0) && std::isfinite(c.m_jacDiagABInv))) {
        continue;
      }
      const int jac_index = on_a ? c.m_jacAindex : c.m_jacBindex;
      row.jac = &m_data.m_jacobians[jac_index];
      row.unit = &m_data.m_deltaVelocitiesUnitImpulse[jac_index];
      row.vel = &m_data.m_deltaVelocities[on_a ? c.m_deltaVelAindex : c.m_deltaVelBindex];
      row.body_vel = const_cast<btScalar*>(body->getDeltaVelocityVector());
      row.body = body;
    }
  }

  // Index of the only non-zero Jacobian entry of a row on one multibody (side A), or -1.
  int singleNonZero(const btMultiBodySolverConstraint& c) const {
    if (!c.m_multiBodyA || c.m_multiBodyB || c.m_solverBodyIdB >= 0) return -1;
    const int ndof = c.m_multiBodyA->getNumDofs() + 6;
    int found = -1;
    for (int i = 0; i < ndof; ++i) {
      if (m_data.m_jacobians[c.m_jacAindex + i] == btScalar(0)) continue;
      if (found >= 0) return -1;
      found = i;
    }
    return found;
  }

  static void setLimits(btMultiBodySolverConstraint& c, btScalar totalImpulse) {
    c.m_lowerLimit = -(c.m_friction * totalImpulse);
    c.m_upperLimit = c.m_friction * totalImpulse;
  }

  static void markMoved(const Row& row) {
    if (row.body != nullptr) {
      row.body->setPosUpdated(false);
    } else {
      markMoved(*row.c);
    }
  }

  static void markMoved(const btMultiBodySolverConstraint& c) {
    if (c.m_multiBodyA) c.m_multiBodyA->setPosUpdated(false);
    if (c.m_multiBodyB) c.m_multiBodyB->setPosUpdated(false);
  }

  // Sequential dot product of a row's Jacobian with the accumulated velocity change, as
  // Bullet's loop computes it. With the size known at compile time (kRobotDofs) the loop is
  // unrolled; a run-time size costs several times more in loop and alias checks.
  template <int N>
  static btScalar dotFixed(const btScalar* jac, const btScalar* vel) {
    btScalar sum = 0;
    for (int i = 0; i < N; ++i) sum += jac[i] * vel[i];
    return sum;
  }

  // The same products summed as two 4-lane halves, then the lanes pairwise: three dependent
  // additions instead of eight.
  static btScalar dotPairwise8(const btScalar* jac, const btScalar* vel) {
    btScalar p[8];
    for (int i = 0; i < 8; ++i) p[i] = jac[i] * vel[i];
    const btScalar c0 = p[0] + p[4], c1 = p[1] + p[5], c2 = p[2] + p[6], c3 = p[3] + p[7];
    return (c0 + c2) + (c1 + c3);
  }

  btScalar dot(int jac_index, int vel_index, int ndof) const {
    const btScalar* jac = &m_data.m_jacobians[jac_index];
    const btScalar* vel = &m_data.m_deltaVelocities[vel_index];
    if (ndof == kRobotDofs) {
      return def_.pairwise_dots ? dotPairwise8(jac, vel) : dotFixed<kRobotDofs>(jac, vel);
    }
    btScalar sum = 0;
    for (int i = 0; i < ndof; ++i) sum += jac[i] * vel[i];
    return sum;
  }

  // The unclamped impulse change of a row: Bullet's deltaImpulse before the limits.
  // `single` >= 0: the row's only non-zero Jacobian entry on side A. Summing that one product
  // onto zero gives Bullet's sum exactly: the other products are zeros (for finite
  // velocities), and adding a zero to a sum that started at +0 changes neither its value nor,
  // since a round-to-nearest sum of zero is +0, its sign.
  btScalar unclampedDelta(const btMultiBodySolverConstraint& c, int& ndofA, int& ndofB,
                          btSolverBody*& bodyA, btSolverBody*& bodyB, int single = -1) {
    btScalar deltaImpulse = c.m_rhs - btScalar(c.m_appliedImpulse) * c.m_cfm;
    btScalar deltaVelADotn = 0;
    btScalar deltaVelBDotn = 0;
    if (c.m_multiBodyA) {
      ndofA = c.m_multiBodyA->getNumDofs() + 6;
      if (single >= 0) {
        deltaVelADotn += m_data.m_jacobians[c.m_jacAindex + single] *
                         m_data.m_deltaVelocities[c.m_deltaVelAindex + single];
      } else {
        deltaVelADotn += dot(c.m_jacAindex, c.m_deltaVelAindex, ndofA);
      }
    } else if (c.m_solverBodyIdA >= 0) {
      bodyA = &m_tmpSolverBodyPool[c.m_solverBodyIdA];
      deltaVelADotn += c.m_contactNormal1.dot(bodyA->internalGetDeltaLinearVelocity()) +
                       c.m_relpos1CrossNormal.dot(bodyA->internalGetDeltaAngularVelocity());
    }
    if (c.m_multiBodyB) {
      ndofB = c.m_multiBodyB->getNumDofs() + 6;
      deltaVelBDotn += dot(c.m_jacBindex, c.m_deltaVelBindex, ndofB);
    } else if (c.m_solverBodyIdB >= 0) {
      bodyB = &m_tmpSolverBodyPool[c.m_solverBodyIdB];
      deltaVelBDotn += c.m_contactNormal2.dot(bodyB->internalGetDeltaLinearVelocity()) +
                       c.m_relpos2CrossNormal.dot(bodyB->internalGetDeltaAngularVelocity());
    }
    deltaImpulse -= deltaVelADotn * c.m_jacDiagABInv;
    deltaImpulse -= deltaVelBDotn * c.m_jacDiagABInv;
    return deltaImpulse;
  }

  template <int N>
  static void axpyFixed(const btScalar* unit, btScalar impulse, btScalar* __restrict vel,
                        btScalar* __restrict body_vel) {
    for (int i = 0; i < N; ++i) vel[i] += unit[i] * impulse;
    for (int i = 0; i < N; ++i) body_vel[i] += unit[i] * impulse;
  }

  // Bullet's applyDeltaVee followed by btMultiBody::applyDeltaVeeMultiDof2: the solver's
  // accumulated velocity change and the body's own (its delta-velocity vector, which Bullet
  // only exposes read-only; the body is not const, so writing through it is what
  // applyDeltaVeeMultiDof2 does).
  void applyToMultiBody(btMultiBody* body, int jac_index, int vel_index, int ndof,
                        btScalar impulse) {
    const btScalar* unit = &m_data.m_deltaVelocitiesUnitImpulse[jac_index];
    btScalar* vel = &m_data.m_deltaVelocities[vel_index];
    if (ndof == kRobotDofs) {
      axpyFixed<kRobotDofs>(unit, impulse, vel,
                            const_cast<btScalar*>(body->getDeltaVelocityVector()));
      return;
    }
    for (int i = 0; i < ndof; ++i) vel[i] += unit[i] * impulse;
    body->applyDeltaVeeMultiDof2(unit, impulse);
  }

  void apply(const btMultiBodySolverConstraint& c, btScalar impulse, int ndofA, int ndofB,
             btSolverBody* bodyA, btSolverBody* bodyB) {
    if (c.m_multiBodyA) {
      applyToMultiBody(c.m_multiBodyA, c.m_jacAindex, c.m_deltaVelAindex, ndofA, impulse);
    } else if (c.m_solverBodyIdA >= 0) {
      bodyA->internalApplyImpulse(c.m_contactNormal1 * bodyA->internalGetInvMass(),
                                  c.m_angularComponentA, impulse);
    }
    if (c.m_multiBodyB) {
      applyToMultiBody(c.m_multiBodyB, c.m_jacBindex, c.m_deltaVelBindex, ndofB, impulse);
    } else if (c.m_solverBodyIdB >= 0) {
      bodyB->internalApplyImpulse(c.m_contactNormal2 * bodyB->internalGetInvMass(),
                                  c.m_angularComponentB, impulse);
    }
  }

  // resolveSingleConstraintRowGeneric.
  btScalar solveRow(const btMultiBodySolverConstraint& c, int single = -1) {
    int ndofA = 0;
    int ndofB = 0;
    btSolverBody* bodyA = nullptr;
    btSolverBody* bodyB = nullptr;
    const btScalar deltaImpulse = clamp(c, unclampedDelta(c, ndofA, ndofB, bodyA, bodyB, single));
    apply(c, deltaImpulse, ndofA, ndofB, bodyA, bodyB);
    return deltaImpulse / c.m_jacDiagABInv;
  }

  // The row's impulse change kept within its limits, the impulse updated: Bullet's clamp.
  static btScalar clamp(const btMultiBodySolverConstraint& c, btScalar deltaImpulse) {
    const btScalar sum = btScalar(c.m_appliedImpulse) + deltaImpulse;
    if (sum < c.m_lowerLimit) {
      deltaImpulse = c.m_lowerLimit - c.m_appliedImpulse;
      c.m_appliedImpulse = c.m_lowerLimit;
    } else if (sum > c.m_upperLimit) {
      deltaImpulse = c.m_upperLimit - c.m_appliedImpulse;
      c.m_appliedImpulse = c.m_upperLimit;
    } else {
      c.m_appliedImpulse = sum;
    }
    return deltaImpulse;
  }

  // unclampedDelta for a resolved row: the multibody's dot product, the fixed side's +0 left
  // out (see Row).
  template <bool kPairwise>
  static btScalar robotDelta(const Row& row) {
    const btMultiBodySolverConstraint& c = *row.c;
    btScalar deltaImpulse = c.m_rhs - btScalar(c.m_appliedImpulse) * c.m_cfm;
    btScalar deltaVelDotn = 0;
    if (row.single >= 0) {
      deltaVelDotn += row.jac[row.single] * row.vel[row.single];
    } else {
      deltaVelDotn +=
          kPairwise ? dotPairwise8(row.jac, row.vel) : dotFixed<kRobotDofs>(row.jac, row.vel);
    }
    deltaImpulse -= deltaVelDotn * c.m_jacDiagABInv;
    return deltaImpulse;
  }

  // solveRow for a row of either kind.
  template <bool kPairwise>
  btScalar solve(const Row& row) {
    if (row.jac == nullptr) return solveRow(*row.c, row.single);
    const btScalar deltaImpulse = clamp(*row.c, robotDelta<kPairwise>(row));
    axpyFixed<kRobotDofs>(row.unit, deltaImpulse, row.vel, row.body_vel);
    return deltaImpulse / row.c->m_jacDiagABInv;
  }

  // resolveConeFrictionConstraintRows, except for a pair whose friction cone has radius zero
  // (no friction, as the slider's, or no normal impulse, as a contact at positive distance)
  // and that carries no impulse yet: Bullet clamps both sums into the zero cone, leaving both
  // impulses at zero, applies changes of zero (an atan2, a sin and a cos later) and reports a
  // zero residual. Skipping the pair leaves the same state (up to the sign of an exact zero).
  // Rows of one resolved multibody take the resolved path; others Bullet's.
  template <bool kPairwise>
  btScalar solveConePair(const Row& rowA, const Row& rowB) {
    const btMultiBodySolverConstraint& cA = *rowA.c;
    const btMultiBodySolverConstraint& cB = *rowB.c;
    if (cA.m_lowerLimit == btScalar(0) && cB.m_lowerLimit == btScalar(0) &&
        btScalar(cA.m_appliedImpulse) == btScalar(0) &&
        btScalar(cB.m_appliedImpulse) == btScalar(0)) {
      return 0;
    }
    if (rowA.jac == nullptr || rowB.jac == nullptr) return solveConePair(cA, cB);
    // Bullet computes B's row first, then A's, both before applying either.
    btScalar deltaImpulseB = robotDelta<kPairwise>(rowB);
    btScalar deltaImpulseA = robotDelta<kPairwise>(rowA);
    clampCone(cA, cB, deltaImpulseA, deltaImpulseB);
    axpyFixed<kRobotDofs>(rowA.unit, deltaImpulseA, rowA.vel, rowA.body_vel);
    axpyFixed<kRobotDofs>(rowB.unit, deltaImpulseB, rowB.vel, rowB.body_vel);
    return deltaImpulseA / cA.m_jacDiagABInv + deltaImpulseB / cB.m_jacDiagABInv;
  }

  btScalar solveConePair(const btMultiBodySolverConstraint& cA,
                         const btMultiBodySolverConstraint& cB) {
    int ndofA = 0;
    int ndofB = 0;
    btSolverBody* bodyA = nullptr;
    btSolverBody* bodyB = nullptr;
    // Bullet computes B's row first, then A's, both before applying either.
    btScalar deltaImpulseB = unclampedDelta(cB, ndofA, ndofB, bodyA, bodyB);
    btScalar deltaImpulseA = unclampedDelta(cA, ndofA, ndofB, bodyA, bodyB);
    clampCone(cA, cB, deltaImpulseA, deltaImpulseB);
    apply(cA, deltaImpulseA, ndofA, ndofB, bodyA, bodyB);
    apply(cB, deltaImpulseB, ndofA, ndofB, bodyA, bodyB);
    return deltaImpulseA / cA.m_jacDiagABInv + deltaImpulseB / cB.m_jacDiagABInv;
  }

  // Both impulses kept within the friction cone, as Bullet clamps them.
  static void clampCone(const btMultiBodySolverConstraint& cA,
                        const btMultiBodySolverConstraint& cB, btScalar& deltaImpulseA,
                        btScalar& deltaImpulseB) {
    const btScalar sumB = btScalar(cB.m_appliedImpulse) + deltaImpulseB;
    const btScalar sumA = btScalar(cA.m_appliedImpulse) + deltaImpulseA;

    if (sumA * sumA + sumB * sumB >= cA.m_lowerLimit * cB.m_lowerLimit) {
      const btScalar angle = btAtan2(sumA, sumB);
      const btScalar sumAclipped = btFabs(cA.m_lowerLimit * btSin(angle));
      const btScalar sumBclipped = btFabs(cB.m_lowerLimit * btCos(angle));
      if (sumA < -sumAclipped) {
        deltaImpulseA = -sumAclipped - cA.m_appliedImpulse;
        cA.m_appliedImpulse = -sumAclipped;
      } else if (sumA > sumAclipped) {
        deltaImpulseA = sumAclipped - cA.m_appliedImpulse;
        cA.m_appliedImpulse = sumAclipped;
      } else {
        cA.m_appliedImpulse = sumA;
      }
      if (sumB < -sumBclipped) {
        deltaImpulseB = -sumBclipped - cB.m_appliedImpulse;
        cB.m_appliedImpulse = -sumBclipped;
      } else if (sumB > sumBclipped) {
        deltaImpulseB = sumBclipped - cB.m_appliedImpulse;
        cB.m_appliedImpulse = sumBclipped;
      } else {
        cB.m_appliedImpulse = sumB;
      }
    } else {
      cA.m_appliedImpulse = sumA;
      cB.m_appliedImpulse = sumB;
    }
  }
};

}  // namespace

std::unique_ptr<btMultiBodyConstraintSolver> makeFastMultiBodySolver(const FastSolverDef& def) {
  return std::make_unique<FastMultiBodySolver>(def);
}

}  // namespace parksim
