#pragma once
// The ground of the dynamics world: a box slab whose top face is z = 0, not a
// btStaticPlaneShape. Plane contacts are made by perturbing the box, which nudged every resting
// parked robot by 0.03 mm on its first awake step; the box-box detector gives exact corner
// contacts. The detector's float rounding grows with the slab's size (a 200 m slab rounds
// contact points by ~1e-5 m), so the slab spans the lot plus a metre, and in a large lot only
// the region the robot drives in plus a margin. Internal to sim/.

#include <optional>

#include <Eigen/Core>

#include "parksim/core/model/Scenario.h"

namespace parksim {

struct GroundSlab {
  Eigen::Vector2d center{0.0, 0.0};        ///< lot frame, m
  Eigen::Vector2d half_extents{0.0, 0.0};  ///< m
  double half_thickness_m = 0.05;          ///< the slab's centre is this far below z = 0, m
};

/// The lot plus 1 m on every side; with `reach` (where the robot is expected to drive), that
/// region plus `margin_m`, clipped to the lot plus 1 m, along each axis where the region does
/// not already cover the whole of it.
GroundSlab groundSlab(const LotBounds& lot, const std::optional<LotBounds>& reach, double margin_m);

}  // namespace parksim
