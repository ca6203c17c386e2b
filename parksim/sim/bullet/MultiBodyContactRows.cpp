#include "parksim/sim/bullet/MultiBodyContactRows.h"

#include <BulletCollision/NarrowPhaseCollision/btPersistentManifold.h>
#include <BulletDynamics/ConstraintSolver/btContactSolverInfo.h>
#include <BulletDynamics/ConstraintSolver/btSolverBody.h>
#include <BulletDynamics/Featherstone/btMultiBody.h>
#include <BulletDynamics/Featherstone/btMultiBodyConstraint.h>
#include <BulletDynamics/Featherstone/btMultiBodyLinkCollider.h>
#include <BulletDynamics/Featherstone/btMultiBodySolverConstraint.h>

#include "parksim/sim/bullet/MultiBodyInverseMass.h"

namespace parksim {

namespace {

constexpr int kUnsupportedPointFlags =
    BT_CONTACT_FLAG_HAS_CONTACT_CFM | BT_CONTACT_FLAG_HAS_CONTACT_ERP |
    BT_CONTACT_FLAG_CONTACT_STIFFNESS_DAMPING | BT_CONTACT_FLAG_FRICTION_ANCHOR;

bool supported(const btPersistentManifold& manifold, const btContactSolverInfo& info) {
  if ((info.m_solverMode & SOLVER_USE_2_FRICTION_DIRECTIONS) == 0 ||
      (info.m_solverMode & SOLVER_ENABLE_FRICTION_DIRECTION_CACHING) != 0 ||
      (info.m_solverMode & SOLVER_USE_ARTICULATED_WARMSTARTING) != 0) {
    return false;
  }
  for (const btCollisionObject* o : {manifold.getBody0(), manifold.getBody1()}) {
    if (o->hasAnisotropicFriction(btCollisionObject::CF_ANISOTROPIC_FRICTION |
                                  btCollisionObject::CF_ANISOTROPIC_ROLLING_FRICTION)) {
      return false;
    }
  }
  for (int j = 0; j < manifold.getNumContacts(); ++j) {
    const btManifoldPoint& cp = manifold.getContactPoint(j);
    if ((cp.m_contactPointFlags & kUnsupportedPointFlags) != 0 ||
        cp.m_combinedRollingFriction > 0 || cp.m_combinedSpinningFriction > 0) {
      return false;
    }
  }
  return true;
}

// Bullet's fillContactJacobianMultiDof (fillConstraintJacobianMultiDof without an angular part)
// in the world frame for a link attached to the base by a revolute or fixed joint: the base's
// entries [(p - base) x n, n], the joint's n . (axis x (p - link centre) + axis bottom). Bullet
// walks the chain in each link's frame; turned to the world the products are the same up to
// rounding. Other links take Bullet's own.
void fillJacobian(btMultiBody& body, int link, const btVector3& point, const btVector3& normal,
                  btScalar* jac, btMultiBodyJacobianData& data) {
  const btMultibodyLink* l = link >= 0 ? &body.getLink(link) : nullptr;
  if (l != nullptr && (l->m_parent != -1 || (l->m_jointType != btMultibodyLink::eRevolute &&
                                             l->m_jointType != btMultibodyLink::eFixed))) {
    body.fillContactJacobianMultiDof(link, point, normal, jac, data.scratch_r, data.scratch_v,
                                     data.scratch_m);
    return;
  }
  const btVector3 omega = (point - body.getBasePos()).cross(normal);
  for (int i = 0; i < 3; ++i) {
    jac[i] = omega[i];
    jac[3 + i] = normal[i];
  }
  const int ndof = body.getNumDofs();
  for (int i = 6; i < 6 + ndof; ++i) jac[i] = 0;
  if (l == nullptr || l->m_jointType != btMultibodyLink::eRevolute) return;
  const btQuaternion& rotation = l->m_cachedWorldTransform.getRotation();
  const btVector3 top = quatRotate(rotation, l->getAxisTop(0));
  const btVector3 bottom = quatRotate(rotation, l->getAxisBottom(0));
  const btVector3 arm = point - l->m_cachedWorldTransform.getOrigin();
  jac[6 + l->m_dofOffset] = normal.dot(top.cross(arm) + bottom);
}

// One side of a row: the multibody's Jacobian and response, or the fixed body's terms.
struct Side {
  btMultiBody* body = nullptr;
  int link = -1;
  int solver_body = -1;
};

// Bullet's setupMultiBodyContactConstraint for a multibody against a fixed body (rb0 or rb1 is
// null there, so its rigid-body terms vanish); the multibody's response from the inverse mass.
void setupRow(btMultiBodySolverConstraint& c, const btVector3& normal, btManifoldPoint& cp,
              const btContactSolverInfo& info, bool is_friction, ContactRowTarget& t) {
  btMultiBodyJacobianData& data = t.data;
  btVector3 rel_pos1;
  btVector3 rel_pos2;
  const btVector3& pos1 = cp.getPositionWorldOnA();
  const btVector3& pos2 = cp.getPositionWorldOnB();
  if (c.m_multiBodyA == nullptr) {
    rel_pos1 = pos1 - t.bodies[c.m_solverBodyIdA].getWorldTransform().getOrigin();
  }
  if (c.m_multiBodyB == nullptr) {
    rel_pos2 = pos2 - t.bodies[c.m_solverBodyIdB].getWorldTransform().getOrigin();
  }
  const btScalar relaxation = info.m_sor;
  const btScalar inv_time_step = btScalar(1) / info.m_timeStep;
  btScalar cfm = is_friction ? info.m_frictionCFM : info.m_globalCfm;
  const btScalar erp = is_friction ? info.m_frictionERP : info.m_erp2;
  cfm *= inv_time_step;

  // The multibody side: index of its velocities, the Jacobian, the response.
  auto multibody = [&](btMultiBody* body, int link, const btVector3& pos, const btVector3& n,
                       int& vel_index, int& jac_index) {
    const int ndof = body->getNumDofs() + 6;
    vel_index = body->getCompanionId();
    if (vel_index < 0) {
      vel_index = data.m_deltaVelocities.size();
      body->setCompanionId(vel_index);
      data.m_deltaVelocities.resize(data.m_deltaVelocities.size() + ndof);
    }
    jac_index = data.m_jacobians.size();
    data.m_jacobians.resize(data.m_jacobians.size() + ndof);
    data.m_deltaVelocitiesUnitImpulse.resize(data.m_deltaVelocitiesUnitImpulse.size() + ndof);
    fillJacobian(*body, link, pos, n, &data.m_jacobians[jac_index], data);
    t.inverse_mass.respond(*body, jac_index, data);
    const btVector3 origin =
        link < 0 ? body->getBasePos() : body->getLink(link).m_cachedWorldTransform.getOrigin();
    return pos - origin;
  };
  if (c.m_multiBodyA != nullptr) {
    rel_pos1 =
        multibody(c.m_multiBodyA, c.m_linkA, pos1, normal, c.m_deltaVelAindex, c.m_jacAindex);
    c.m_relpos1CrossNormal = rel_pos1.cross(normal);
    c.m_contactNormal1 = normal;
  } else {
    c.m_relpos1CrossNormal = rel_pos1.cross(normal);
    c.m_contactNormal1 = normal;
    c.m_angularComponentA = btVector3(0, 0, 0);
  }
  if (c.m_multiBodyB != nullptr) {
    rel_pos2 =
        multibody(c.m_multiBodyB, c.m_linkB, pos2, -normal, c.m_deltaVelBindex, c.m_jacBindex);
    c.m_relpos2CrossNormal = -rel_pos2.cross(normal);
    c.m_contactNormal2 = -normal;
  } else {
    c.m_relpos2CrossNormal = -rel_pos2.cross(normal);
    c.m_contactNormal2 = -normal;
    c.m_angularComponentB = btVector3(0, 0, 0);
  }

  // Effective mass and relative velocity, from the multibody side only.
  btScalar denom = 0;
  btScalar rel_vel = 0;
  auto terms = [&](btMultiBody* body, int jac_index, btScalar& d) {
    const int ndof = body->getNumDofs() + 6;
    const btScalar* jac = &data.m_jacobians[jac_index];
    const btScalar* lambda = &data.m_deltaVelocitiesUnitImpulse[jac_index];
    for (int i = 0; i < ndof; ++i) d += jac[i] * lambda[i];
  };
  btScalar denom0 = 0;
  btScalar denom1 = 0;
  if (c.m_multiBodyA != nullptr) terms(c.m_multiBodyA, c.m_jacAindex, denom0);
  if (c.m_multiBodyB != nullptr) terms(c.m_multiBodyB, c.m_jacBindex, denom1);
  denom = denom0 + denom1 + cfm;
  c.m_jacDiagABInv = denom > SIMD_EPSILON ? relaxation / denom : btScalar(0);
  auto velocity = [&](btMultiBody* body, int jac_index) {
    const int ndof = body->getNumDofs() + 6;
    const btScalar* jac = &data.m_jacobians[jac_index];
    for (int i = 0; i < ndof; ++i) rel_vel += body->getVelocityVector()[i] * jac[i];
  };
  if (c.m_multiBodyA != nullptr) velocity(c.m_multiBodyA, c.m_jacAindex);
  if (c.m_multiBodyB != nullptr) velocity(c.m_multiBodyB, c.m_jacBindex);
  c.m_friction = cp.m_combinedFriction;

  // Bullet's restitutionCurve, and its positional and velocity errors.
  btScalar restitution = 0;
  if (!is_friction && btFabs(rel_vel) >= info.m_restitutionVelocityThreshold) {
    restitution = btMax(btScalar(0), cp.m_combinedRestitution * -rel_vel);
  }
  const btScalar distance = is_friction ? btScalar(0) : cp.getDistance() + info.m_linearSlop;
  btScalar positional_error = 0;
  btScalar velocity_error = restitution - rel_vel;
  if (!is_friction && distance > 0) {
    velocity_error -= distance / info.m_timeStep;
  } else {
    positional_error = -distance * erp / info.m_timeStep;
  }
  const btScalar penetration_impulse = positional_error * c.m_jacDiagABInv;
  const btScalar velocity_impulse = velocity_error * c.m_jacDiagABInv;
  c.m_rhs = penetration_impulse + velocity_impulse;
  c.m_rhsPenetration = 0;
  c.m_lowerLimit = is_friction ? -c.m_friction : btScalar(0);
  c.m_upperLimit = is_friction ? c.m_friction : btScalar(1e10f);
  c.m_cfm = cfm * c.m_jacDiagABInv;
  c.m_appliedImpulse = 0;
  c.m_appliedPushImpulse = 0;
}

btMultiBodySolverConstraint& addRow(btAlignedObjectArray<btMultiBodySolverConstraint>& rows,
                                    const Side& a, const Side& b, btManifoldPoint& cp) {
  btMultiBodySolverConstraint& c = rows.expandNonInitializing();
  c.m_orgConstraint = nullptr;
  c.m_orgDofIndex = -1;
  c.m_solverBodyIdA = a.solver_body;
  c.m_solverBodyIdB = b.solver_body;
  c.m_multiBodyA = a.body;
  c.m_linkA = a.link;
  c.m_multiBodyB = b.body;
  c.m_linkB = b.link;
  c.m_originalContactPoint = &cp;
  return c;
}

}  // namespace

bool addFixedContactRows(btPersistentManifold& manifold, int solver_body_a, int solver_body_b,
                         const btContactSolverInfo& info, ContactRowTarget& target) {
  const btMultiBodyLinkCollider* fa = btMultiBodyLinkCollider::upcast(manifold.getBody0());
  const btMultiBodyLinkCollider* fb = btMultiBodyLinkCollider::upcast(manifold.getBody1());
  if ((fa == nullptr) == (fb == nullptr)) return false;
  const btMultiBodyLinkCollider* link = fa != nullptr ? fa : fb;
  const int other = fa != nullptr ? solver_body_b : solver_body_a;
  if (!target.inverse_mass.covers(link->m_multiBody) || other < 0 ||
      target.bodies[other].m_originalBody != nullptr || !supported(manifold, info)) {
    return false;
  }
  Side a;
  Side b;
  if (fa != nullptr) {
    a = {fa->m_multiBody, fa->m_link, -1};
    b.solver_body = solver_body_b;
  } else {
    a.solver_body = solver_body_a;
    b = {fb->m_multiBody, fb->m_link, -1};
  }
  for (int j = 0; j < manifold.getNumContacts(); ++j) {
    btManifoldPoint& cp = manifold.getContactPoint(j);
    if (cp.getDistance() > manifold.getContactProcessingThreshold()) {
      // Reset quantities related to warm starting, as Bullet does.
      cp.m_appliedImpulse = 0;
      cp.m_prevRHS = 0;
      continue;
    }
    const int friction_index = target.normals.size();
    btMultiBodySolverConstraint& normal = addRow(target.normals, a, b, cp);
    setupRow(normal, cp.m_normalWorldOnB, cp, info, false, target);
    normal.m_frictionIndex = target.frictions.size();
    btPlaneSpace1(cp.m_normalWorldOnB, cp.m_lateralFrictionDir1, cp.m_lateralFrictionDir2);
    cp.m_lateralFrictionDir1.normalize();
    cp.m_lateralFrictionDir2.normalize();
    for (const btVector3* dir : {&cp.m_lateralFrictionDir1, &cp.m_lateralFrictionDir2}) {
      btMultiBodySolverConstraint& f = addRow(target.frictions, a, b, cp);
      f.m_frictionIndex = friction_index;
      setupRow(f, *dir, cp, info, true, target);
    }
    if ((info.m_solverMode & SOLVER_DISABLE_VELOCITY_DEPENDENT_FRICTION_DIRECTION) != 0) {
      cp.m_contactPointFlags |= BT_CONTACT_FLAG_LATERAL_FRICTION_INITIALIZED;
    }
  }
  return true;
}

}  // namespace parksim
