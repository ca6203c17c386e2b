#pragma once
// The footprint of an obstacle that is not one convex shape: a non-convex polygon, a polygon with
// holes (ConvexPartition.h) or a map's occupied cells merged into rectangles (GridRectangles.h).
// It is held as convex parts, which Bullet (compound shapes) and the exact separating-axis tests
// take as they are. Immutable and shared: a scenario with a map of 100,000 parts is copied by
// copying a pointer.

#include <memory>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace parksim {

struct CompoundShape {
  /// Convex parts, each strictly convex and counter-clockwise, m (lot frame); their union is
  /// the footprint. Their interiors are disjoint but for walls a drawing draws as lines
  /// (scenario/SvgMap.h), each a part of its own that overlaps the others where they meet.
  std::vector<std::vector<Eigen::Vector2d>> parts;
  /// Each part's axis-aligned bounds, m.
  std::vector<Eigen::AlignedBox2d> bounds;
  /// The outline for drawing, m: outer rings counter-clockwise, holes clockwise. Empty for a
  /// map's cells, which are drawn by their parts.
  std::vector<std::vector<Eigen::Vector2d>> rings;
  /// All parts' bounds together.
  Eigen::AlignedBox2d extent;

  /// A shape of `parts` (each strictly convex and counter-clockwise; at least one) with the
  /// outline `rings`; computes the bounds.
  static std::shared_ptr<const CompoundShape> make(std::vector<std::vector<Eigen::Vector2d>> parts,
                                                   std::vector<std::vector<Eigen::Vector2d>> rings);
};

}  // namespace parksim
