#pragma once
// Bullet's multibody constraint solver with a faster inner loop. Internal to sim/ (only
// DynamicsWorld.cpp uses it); the Bullet type is only forward-declared here.

#include <memory>

class btMultiBodyConstraintSolver;

namespace parksim {

/// A btMultiBodyConstraintSolver whose iterations compute what Bullet 3.24's do, in the same
/// order (tested: FastMultiBodySolverTest), with the rows solved inline instead of through
/// four out-of-line calls each, and without the work that provably changes nothing: friction
/// pairs whose cone has radius zero and no impulse (the frictionless slider, contacts without
/// normal impulse), zero terms of a joint motor's Jacobian.
/// `pairwise_dots` false: every float operation as Bullet's, results bit-identical.
/// `pairwise_dots` true: the 8-term dot products are summed as two 4-lane halves instead of
/// left to right, which shortens the solver's serial chain; results differ by rounding.
std::unique_ptr<btMultiBodyConstraintSolver> makeFastMultiBodySolver(bool pairwise_dots);

}  // namespace parksim
