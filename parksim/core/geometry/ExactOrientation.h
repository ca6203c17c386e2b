#pragma once
// The sign of the orientation determinant of three points, exact for any finite doubles. The
// polygon checks and the convex partition decide every turn with it, so their answers never
// depend on rounding: a partition's parts are the polygon's own vertices joined by decisions
// that are right, not nearly right.

#include <Eigen/Core>

namespace parksim {

/// +1 when a, b, c turn counter-clockwise, -1 clockwise, 0 when collinear: the exact sign of
/// (b - a) x (c - a). A filtered double evaluation decides almost every call; the rest are
/// decided by exact expansion arithmetic (error-free sums and products, as Shewchuk's robust
/// predicates do).
int orientation(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c);

}  // namespace parksim
