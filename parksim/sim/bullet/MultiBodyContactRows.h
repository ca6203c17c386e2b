#pragma once
// The constraint solver's rows for the contacts of a multibody with a fixed object (a wheel or
// the slider on the ground, the chassis against a wall or a parked robot not yet woken), set up
// as Bullet 3.24's btMultiBodyConstraintSolver::convertMultiBodyContact does, field for field,
// except that each row's velocity response comes from MultiBodyInverseMass instead of an
// articulated-body pass. Internal to sim/ (FastMultiBodySolver.cpp); Bullet's types are only
// declared here.

template <typename T>
class btAlignedObjectArray;
class btPersistentManifold;
struct btContactSolverInfo;
struct btMultiBodyJacobianData;
struct btMultiBodySolverConstraint;
struct btSolverBody;

namespace parksim {

class MultiBodyInverseMass;

/// The solver's arrays the rows go into.
struct ContactRowTarget {
  btAlignedObjectArray<btMultiBodySolverConstraint>& normals;
  btAlignedObjectArray<btMultiBodySolverConstraint>& frictions;
  btMultiBodyJacobianData& data;
  btAlignedObjectArray<btSolverBody>& bodies;
  MultiBodyInverseMass& inverse_mass;
};

/// Adds the normal row and the two friction rows of every point of `manifold` within its
/// contact processing threshold, and resets the others' warm-start values, as Bullet does.
/// `solver_body_a` / `_b`: the solver body of a side that is not a multibody link (-1 for a
/// link). Adds nothing and returns false unless exactly one side is a link of a multibody that
/// `inverse_mass` covers and the other side is fixed (infinite mass), and the contact needs
/// none of what this does not transcribe (rolling, spinning or anisotropic friction, contact
/// stiffness, CFM or ERP per point, friction anchors, cached friction directions, a single
/// friction direction): Bullet's convertMultiBodyContact must then convert it.
bool addFixedContactRows(btPersistentManifold& manifold, int solver_body_a, int solver_body_b,
                         const btContactSolverInfo& info, ContactRowTarget& target);

}  // namespace parksim
