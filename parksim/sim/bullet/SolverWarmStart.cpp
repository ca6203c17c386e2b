#include "parksim/sim/bullet/SolverWarmStart.h"

#include <BulletDynamics/ConstraintSolver/btSolverBody.h>
#include <BulletDynamics/Featherstone/btMultiBody.h>
#include <BulletDynamics/Featherstone/btMultiBodyConstraint.h>
#include <BulletDynamics/Featherstone/btMultiBodySolverConstraint.h>

namespace parksim {

namespace {

// A contact's normal must stay this close to the last step's (cosine of 0.8 degrees): the
// friction rows' directions follow from it, so an old lateral impulse only fits the same
// normal.
constexpr double kSameNormalCos = 0.9999;

// Whether the row's side that is not a multibody is fixed (infinite mass): the ground, a wall,
// a parked robot not yet woken.
bool fixedOther(const btMultiBodySolverConstraint& c,
                const btAlignedObjectArray<btSolverBody>& bodies) {
  const int other = c.m_multiBodyA != nullptr ? c.m_solverBodyIdB : c.m_solverBodyIdA;
  return other >= 0 && bodies[other].m_originalBody == nullptr;
}

// The multibody side of a contact row, or nullptr when it has none or two.
const btMultiBody* multiBodySide(const btMultiBodySolverConstraint& c, int& link) {
  if (c.m_multiBodyA != nullptr && c.m_multiBodyB == nullptr) {
    link = c.m_linkA;
    return c.m_multiBodyA;
  }
  if (c.m_multiBodyB != nullptr && c.m_multiBodyA == nullptr) {
    link = c.m_linkB;
    return c.m_multiBodyB;
  }
  return nullptr;
}

// Bullet's applyDeltaVee for a multibody, its own velocity change, or a rigid body's impulse.
void applyImpulse(btMultiBodySolverConstraint& c, btScalar impulse, btMultiBodyJacobianData& data,
                  btAlignedObjectArray<btSolverBody>& bodies) {
  c.m_appliedImpulse = impulse;
  if (impulse == btScalar(0)) return;
  auto multi = [&](btMultiBody* body, int jac_index, int vel_index) {
    btScalar* unit = &data.m_deltaVelocitiesUnitImpulse[jac_index];
    body->applyDeltaVeeMultiDof2(unit, impulse);
    const int ndof = body->getNumDofs() + 6;
    for (int i = 0; i < ndof; ++i) data.m_deltaVelocities[vel_index + i] += unit[i] * impulse;
  };
  if (c.m_multiBodyA != nullptr) {
    multi(c.m_multiBodyA, c.m_jacAindex, c.m_deltaVelAindex);
  } else if (c.m_solverBodyIdA >= 0) {
    btSolverBody& b = bodies[c.m_solverBodyIdA];
    b.internalApplyImpulse(c.m_contactNormal1 * b.internalGetInvMass(), c.m_angularComponentA,
                           impulse);
  }
  if (c.m_multiBodyB != nullptr) {
    multi(c.m_multiBodyB, c.m_jacBindex, c.m_deltaVelBindex);
  } else if (c.m_solverBodyIdB >= 0) {
    btSolverBody& b = bodies[c.m_solverBodyIdB];
    b.internalApplyImpulse(c.m_contactNormal2 * b.internalGetInvMass(), c.m_angularComponentB,
                           impulse);
  }
}

}  // namespace

void SolverWarmStart::record(const SolverRows& normals, const SolverRows& frictions,
                             const btAlignedObjectArray<btSolverBody>& bodies) {
  scratch_.clear();
  for (int i = 0; i < normals.size(); ++i) {
    const btMultiBodySolverConstraint& n = normals[i];
    Contact c;
    c.body = multiBodySide(n, c.link);
    if (c.body == nullptr || !fixedOther(n, bodies)) continue;
    const btVector3& normal = n.m_multiBodyA != nullptr ? n.m_contactNormal1 : n.m_contactNormal2;
    for (int k = 0; k < 3; ++k) c.normal[k] = double(normal[k]);
    c.impulse = double(n.m_appliedImpulse);
    c.lateral1 = double(frictions[n.m_frictionIndex].m_appliedImpulse);
    c.lateral2 = double(frictions[n.m_frictionIndex + 1].m_appliedImpulse);
    scratch_.push_back(c);
  }
  // Bullet may solve islands in separate calls: this call's bodies replace their own entries.
  std::erase_if(contacts_, [&](const Contact& old) {
    for (const Contact& c : scratch_) {
      if (c.body == old.body) return true;
    }
    return false;
  });
  // Only links with a single solved point: several points of one link cannot be told apart.
  for (const Contact& c : scratch_) {
    int same = 0;
    for (const Contact& d : scratch_) same += d.body == c.body && d.link == c.link;
    if (same == 1) contacts_.push_back(c);
  }
}

void SolverWarmStart::apply(SolverRows& normals, SolverRows& frictions, SolverRows& non_contact,
                            btMultiBodyJacobianData& data,
                            btAlignedObjectArray<btSolverBody>& bodies) const {
  for (int j = 0; j < non_contact.size(); ++j) {
    btMultiBodySolverConstraint& c = non_contact[j];
    if (c.m_orgConstraint == nullptr) continue;
    applyImpulse(c, c.m_orgConstraint->getAppliedImpulse(c.m_orgDofIndex), data, bodies);
  }
  for (int i = 0; i < normals.size(); ++i) {
    btMultiBodySolverConstraint& n = normals[i];
    int link = 0;
    const btMultiBody* body = multiBodySide(n, link);
    if (body == nullptr || !fixedOther(n, bodies)) continue;
    const Contact* last = nullptr;
    for (const Contact& c : contacts_) {
      if (c.body == body && c.link == link) last = &c;
    }
    if (last == nullptr) continue;
    int same = 0;  // solved points of this link now
    for (int k = 0; k < normals.size(); ++k) {
      int other_link = 0;
      same += multiBodySide(normals[k], other_link) == body && other_link == link &&
              fixedOther(normals[k], bodies);
    }
    const btVector3& normal = n.m_multiBodyA != nullptr ? n.m_contactNormal1 : n.m_contactNormal2;
    const double cos = double(normal[0]) * last->normal[0] + double(normal[1]) * last->normal[1] +
                       double(normal[2]) * last->normal[2];
    if (same != 1 || cos < kSameNormalCos) continue;
    applyImpulse(n, btScalar(last->impulse), data, bodies);
    if (!friction_) continue;
    applyImpulse(frictions[n.m_frictionIndex], btScalar(last->lateral1), data, bodies);
    applyImpulse(frictions[n.m_frictionIndex + 1], btScalar(last->lateral2), data, bodies);
  }
}

}  // namespace parksim
