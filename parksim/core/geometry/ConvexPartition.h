#pragma once
// Any polygon with holes as convex parts, exactly: Bullet's shapes and the exact separating-axis
// tests are convex, so a non-convex obstacle enters them as the parts of a partition. Each hole
// is joined to the outline by a bridge between two mutually visible vertices (Eberly's
// construction, checked exactly), the resulting ring is triangulated by ear clipping, and the
// triangles are merged across every diagonal whose removal leaves both ends convex
// (Hertel-Mehlhorn: at most four times the fewest convex parts). Every turn is decided by the
// exact orientation test, and the parts' vertices are the polygon's own, so the parts cover the
// polygon with neither gaps nor overlaps: a footprint touches the polygon exactly when it
// touches a part.

#include <vector>

#include <Eigen/Core>

#include "parksim/core/geometry/PolygonRegion.h"

namespace parksim {

/// The convex parts of `region`, which must pass regionProblem (either winding): each strictly
/// convex and counter-clockwise, with the region's own vertices (collinear ones dropped); the
/// parts' interiors are disjoint and their union is the region. A convex polygon without holes
/// is one part. Throws Error if the partition could not be completed (it always can for a
/// region that passes regionProblem; the check guards against a defect here).
std::vector<std::vector<Eigen::Vector2d>> convexPartition(const PolygonWithHoles& region);

}  // namespace parksim
