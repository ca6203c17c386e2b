#pragma once
// Bullet's multibody constraint solver with a faster inner loop, optionally warm-started
// (SolverWarmStart.h) and with the rows of multibodies of constant mass matrix set up without
// Bullet's articulated-body pass per row (MultiBodyInverseMass.h). Internal to sim/ (only
// DynamicsWorld.cpp uses it); the Bullet type is only forward-declared here.

#include <memory>

class btMultiBodyConstraintSolver;

namespace parksim {

class MultiBodyInverseMass;

struct FastSolverDef {
  /// false: every float operation of the iterations as Bullet's, results bit-identical.
  /// true: the 8-term dot products are summed as two 4-lane halves instead of left to right,
  /// which shortens the solver's serial chain; results differ by rounding.
  bool pairwise_dots = true;
  /// Rows start from the impulses they ended the last step with (SolverWarmStart.h).
  bool warm_start = true;
  /// With warm_start: contacts' friction rows too. A car (sim/CarBody.h) starts them from zero:
  /// on four wheels its friction forces are statically indeterminate, and started from the
  /// last step's they kept it rocking at rest (1-6 mm/s, period two steps) at some iteration
  /// counts (docs/simulation.md, "A car in Bullet").
  bool warm_start_friction = true;
  /// Not null: the contact rows of the multibodies it covers against fixed objects are set up
  /// from it (MultiBodyContactRows.h) instead of Bullet's articulated-body pass per row;
  /// results differ by rounding. Must outlive the solver.
  MultiBodyInverseMass* inverse_mass = nullptr;
};

/// A btMultiBodyConstraintSolver whose iterations compute what Bullet 3.24's do, in the same
/// order (tested: FastMultiBodySolverTest), with the rows solved inline instead of through
/// four out-of-line calls each, and without the work that provably changes nothing: friction
/// pairs whose cone has radius zero and no impulse (the frictionless slider, contacts without
/// normal impulse), zero terms of a joint motor's Jacobian.
std::unique_ptr<btMultiBodyConstraintSolver> makeFastMultiBodySolver(const FastSolverDef& def);

}  // namespace parksim
