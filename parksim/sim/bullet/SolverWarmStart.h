#pragma once
// Warm starting of the dynamics world's constraint solver: each step's contact and motor rows
// start from the impulses the same rows ended the previous step with, so a robot rolling
// steadily needs a few iterations instead of building its weight, traction and motor torque up
// from zero every step. Internal to sim/ (FastMultiBodySolver.cpp); Bullet's types are only
// declared here.
//
// Why not Bullet's own (SOLVER_USE_ARTICULATED_WARMSTARTING): it keeps a contact's impulses
// on the manifold's contact point, and a rolling wheel's contact point is a new point every step
// (it moves over the sphere by r w dt, 0.42 mm per step at 0.1 m/s, farther than the 0.4 mm
// within which Bullet matches a new point to an old one), so at driving speed nothing carries
// over; and it never warm-starts friction. Measured: with Bullet's, a straight drive curved by
// 1.3e-4 rad/s; with this, driving steadily takes one iteration per step and stays straight.
// Here a contact is a multibody link against a fixed object, with one solved point per step (a
// wheel or the slider on the ground; the chassis against one wall), and its impulses carry over
// while its normal stays the same. Contacts with bodies that move (a woken parked robot) start
// from zero, as Bullet's do: warm-starting them nudged untouched parked robots by 2-13 um.

#include <vector>

template <typename T>
class btAlignedObjectArray;
struct btMultiBodySolverConstraint;
struct btMultiBodyJacobianData;
struct btSolverBody;

namespace parksim {

using SolverRows = btAlignedObjectArray<btMultiBodySolverConstraint>;

class SolverWarmStart {
 public:
  /// `friction` false: contacts' friction rows start from zero (a car's, DynamicsWorld.cpp).
  explicit SolverWarmStart(bool friction = true) : friction_(friction) {}

  /// After a step's iterations: remembers the normal and friction impulses of every contact
  /// (see above). `frictions` holds two rows per normal row, at its m_frictionIndex.
  void record(const SolverRows& normals, const SolverRows& frictions,
              const btAlignedObjectArray<btSolverBody>& bodies);

  /// After a step's setup, before its iterations: starts the contact rows that match a
  /// contact of the last step, and every motor row (`non_contact` rows of a multibody
  /// constraint; Bullet keeps their last impulse on the constraint), at those impulses, and
  /// applies the velocity changes they make, as Bullet's own warm start does.
  void apply(SolverRows& normals, SolverRows& frictions, SolverRows& non_contact,
             btMultiBodyJacobianData& data, btAlignedObjectArray<btSolverBody>& bodies) const;

 private:
  struct Contact {
    const void* body = nullptr;  // the btMultiBody
    int link = 0;
    double normal[3] = {0.0, 0.0, 0.0};
    double impulse = 0.0;
    double lateral1 = 0.0;
    double lateral2 = 0.0;
  };
  bool friction_ = true;
  std::vector<Contact> contacts_;
  std::vector<Contact> scratch_;
};

}  // namespace parksim
