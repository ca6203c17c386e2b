#include "parksim/sim/bullet/WheelMotor.h"

#include <BulletDynamics/ConstraintSolver/btContactSolverInfo.h>
#include <BulletDynamics/Featherstone/btMultiBody.h>
#include <BulletDynamics/Featherstone/btMultiBodyJointMotor.h>

#include "parksim/sim/bullet/MultiBodyInverseMass.h"

namespace parksim {

namespace {

// btMultiBodyJointMotor::createConstraintRows and the parts of
// btMultiBodyConstraint::fillMultiBodyConstraint it uses (Bullet 3.24) for a revolute joint of
// one multibody, field for field, with the response from MultiBodyInverseMass.
class WheelMotor final : public btMultiBodyJointMotor {
 public:
  WheelMotor(btMultiBody& body, int link, btScalar max_impulse, MultiBodyInverseMass& inverse_mass)
      : btMultiBodyJointMotor(&body, link, 0, max_impulse), inverse_mass_(inverse_mass) {}

  void createConstraintRows(btMultiBodyConstraintArray& rows, btMultiBodyJacobianData& data,
                            const btContactSolverInfo& info) override {
    if (!inverse_mass_.covers(m_bodyA) ||
        m_bodyA->getLink(m_linkA).m_jointType != btMultibodyLink::eRevolute) {
      btMultiBodyJointMotor::createConstraintRows(rows, data, info);
      return;
    }
    if (m_numDofsFinalized != m_jacSizeBoth) finalizeMultiDof();
    if (m_numDofsFinalized != m_jacSizeBoth) return;  // as Bullet: don't crash
    if (m_maxAppliedImpulse == 0.f) return;
    for (int row = 0; row < getNumRows(); row++)
      addRow(rows.expandNonInitializing(), row, data, info);
  }

 private:
  void addRow(btMultiBodySolverConstraint& c, int row, btMultiBodyJacobianData& data,
              const btContactSolverInfo& info) {
    const int dof = 0;
    const btScalar position = m_bodyA->getJointPosMultiDof(m_linkA)[dof];
    const btScalar velocity = m_bodyA->getJointVelMultiDof(m_linkA)[dof];
    const btScalar stabilisation = m_erp * (m_desiredPosition - position) / info.m_timeStep;
    btScalar rhs = m_kp * stabilisation + velocity + m_kd * (m_desiredVelocity - velocity);
    rhs = btMin(btMax(rhs, -m_rhsClamp), m_rhsClamp);

    c.m_multiBodyA = m_bodyA;
    c.m_multiBodyB = nullptr;
    c.m_linkA = m_linkA;
    c.m_linkB = -1;
    c.m_solverBodyIdA = -1;
    c.m_solverBodyIdB = -1;
    const int ndof = m_bodyA->getNumDofs() + 6;
    c.m_deltaVelAindex = m_bodyA->getCompanionId();
    if (c.m_deltaVelAindex < 0) {
      c.m_deltaVelAindex = data.m_deltaVelocities.size();
      m_bodyA->setCompanionId(c.m_deltaVelAindex);
      data.m_deltaVelocities.resize(data.m_deltaVelocities.size() + ndof);
    }
    c.m_jacAindex = data.m_jacobians.size();
    data.m_jacobians.resize(data.m_jacobians.size() + ndof);
    const btScalar* jac = jacobianA(row);
    for (int i = 0; i < ndof; i++) data.m_jacobians[c.m_jacAindex + i] = jac[i];
    data.m_deltaVelocitiesUnitImpulse.resize(data.m_deltaVelocitiesUnitImpulse.size() + ndof);
    inverse_mass_.respond(*m_bodyA, c.m_jacAindex, data);

    btScalar denom = 0;
    btScalar rel_vel = 0;
    for (int i = 0; i < ndof; ++i) {
      denom += data.m_jacobians[c.m_jacAindex + i] *
               data.m_deltaVelocitiesUnitImpulse[c.m_jacAindex + i];
    }
    for (int i = 0; i < ndof; ++i) {
      rel_vel += m_bodyA->getVelocityVector()[i] * data.m_jacobians[c.m_jacAindex + i];
    }
    c.m_jacDiagABInv = denom > SIMD_EPSILON ? btScalar(1) / denom : btScalar(0);
    c.m_friction = 0;
    c.m_appliedImpulse = 0;
    c.m_appliedPushImpulse = 0;
    // No position error: -0 x erp / dt, as Bullet computes it.
    const btScalar positional_error = -btScalar(0) * info.m_erp / info.m_timeStep;
    c.m_rhs = positional_error * c.m_jacDiagABInv + (rhs - rel_vel) * c.m_jacDiagABInv;
    c.m_rhsPenetration = 0;
    c.m_cfm = 0;
    c.m_lowerLimit = -m_maxAppliedImpulse;
    c.m_upperLimit = m_maxAppliedImpulse;
    c.m_orgConstraint = this;
    c.m_orgDofIndex = row;
    c.m_contactNormal1.setZero();
    c.m_contactNormal2.setZero();
    c.m_angularComponentA.setZero();
    c.m_angularComponentB.setZero();
    const btMultibodyLink& link = m_bodyA->getLink(m_linkA);
    const btVector3 axis =
        quatRotate(link.m_cachedWorldTransform.getRotation(), link.m_axes[0].m_topVec);
    c.m_relpos1CrossNormal = axis;
    c.m_relpos2CrossNormal = -axis;
  }

  MultiBodyInverseMass& inverse_mass_;
};

}  // namespace

std::unique_ptr<btMultiBodyJointMotor> makeWheelMotor(btMultiBody& body, int link,
                                                      double max_impulse,
                                                      MultiBodyInverseMass& inverse_mass) {
  return std::make_unique<WheelMotor>(body, link, btScalar(max_impulse), inverse_mass);
}

}  // namespace parksim
