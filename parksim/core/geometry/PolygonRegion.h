#pragma once
// A polygon with holes as an obstacle's outline: a simple outer ring and simple holes inside it,
// apart from each other. Any simple polygon may be an obstacle; the checks here say what makes
// one unusable, in words a world file's message can carry. Every decision is exact
// (ExactOrientation.h): a polygon passes or fails the same way on every machine.

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace parksim {

struct PolygonWithHoles {
  std::vector<Eigen::Vector2d> outer;               ///< m, either winding
  std::vector<std::vector<Eigen::Vector2d>> holes;  ///< m, either winding
};

/// Most vertices one polygon may have, its holes included (docs/limits.md): the checks and the
/// partition take about n^2 / 2 exact tests at worst.
inline constexpr std::size_t kMaxPolygonRegionVertices = 20000;

/// What makes `region` unusable as an obstacle's outline, or nothing. Each ring: at least 3
/// vertices, finite, no vertex repeated, not all on one line, no edge crossing or touching
/// another except its two neighbours at their shared ends (a simple polygon). Each hole lies
/// inside the outer ring without touching it, and holes neither touch nor contain each other.
/// At most kMaxPolygonRegionVertices vertices. The words name the ring ("hole 2", counted from
/// 0) and the vertex.
std::optional<std::string> regionProblem(const PolygonWithHoles& region);

/// What makes `rings` unusable as the outlines of one drawing's shape, or nothing: each ring as
/// in regionProblem (simple, at least 3 vertices, finite, some area) and no two rings crossing
/// or touching; the words name the ring ("subpath 2"). How they nest is not checked.
std::optional<std::string> ringsProblem(const std::vector<std::vector<Eigen::Vector2d>>& rings);

/// The same region with vertices that lie on the line between their neighbours dropped (they
/// do not change it), the outer ring counter-clockwise and the holes clockwise. `region` must
/// pass regionProblem.
PolygonWithHoles normalizedRegion(const PolygonWithHoles& region);

/// Twice the signed area of a ring (positive counter-clockwise), and of a region (outer ring
/// less the holes, positive), m^2.
double regionDoubleArea(const PolygonWithHoles& region);

/// True when `p` lies inside the region: inside the outer ring and outside every hole, by the
/// crossing number with exact turn tests. Points on the boundary count as inside.
bool insideRegion(const PolygonWithHoles& region, const Eigen::Vector2d& p);

/// True when segments ab and cd share any point (crossing, touching or overlapping), exactly.
bool segmentsMeet(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c,
                  const Eigen::Vector2d& d);

}  // namespace parksim
