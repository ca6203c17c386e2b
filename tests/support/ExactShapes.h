#pragma once
// Test support: exact signed distances between a footprint box and an obstacle of any shape,
// computed independently of core's separating-axis code and of Bullet: for boxes and convex
// polygons, the signed distance of the origin to their Minkowski difference (the convex hull
// of all vertex differences); for circles, the signed distance of the centre to the box's
// outline, less the radius.

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <Eigen/Core>

#include "parksim/core/model/Geometry.h"
#include "parksim/core/model/Scenario.h"

namespace parksim::testing {

inline double crossOf(const Eigen::Vector2d& o, const Eigen::Vector2d& u,
                      const Eigen::Vector2d& v) {
  return (u - o).x() * (v - o).y() - (u - o).y() * (v - o).x();
}

/// Counter-clockwise hull (Andrew's monotone chain), collinear points dropped.
inline std::vector<Eigen::Vector2d> hullOf(std::vector<Eigen::Vector2d> points) {
  std::sort(points.begin(), points.end(), [](const Eigen::Vector2d& u, const Eigen::Vector2d& v) {
    return u.x() < v.x() || (u.x() == v.x() && u.y() < v.y());
  });
  std::vector<Eigen::Vector2d> hull(2 * points.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    while (k >= 2 && crossOf(hull[k - 2], hull[k - 1], points[i]) <= 0) --k;
    hull[k++] = points[i];
  }
  for (std::size_t i = points.size() - 1, lower = k + 1; i-- > 0;) {
    while (k >= lower && crossOf(hull[k - 2], hull[k - 1], points[i]) <= 0) --k;
    hull[k++] = points[i];
  }
  hull.resize(k - 1);
  return hull;
}

/// Signed distance of point p to a counter-clockwise convex polygon: positive outside,
/// negative inside (minus the distance to the nearest edge).
inline double signedDistanceToConvex(const std::vector<Eigen::Vector2d>& poly,
                                     const Eigen::Vector2d& p) {
  bool inside = true;
  double nearest = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const Eigen::Vector2d& a = poly[i];
    const Eigen::Vector2d& b = poly[(i + 1) % poly.size()];
    if (crossOf(a, b, p) < 0) inside = false;
    const Eigen::Vector2d ab = b - a;
    const double t = std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
    nearest = std::min(nearest, (p - (a + t * ab)).norm());
  }
  return inside ? -nearest : nearest;
}

/// Exact signed distance between the footprint box and the obstacle, m: the gap when apart,
/// minus the penetration depth (the shortest move that separates them) when overlapping.
inline double exactSignedDistance(const OrientedBox& footprint, const Obstacle& o) {
  std::vector<Eigen::Vector2d> fp;
  for (const Eigen::Vector2d& c : footprint.corners()) fp.push_back(c);
  if (o.shape == ObstacleShape::kCircle) {
    return signedDistanceToConvex(hullOf(fp), o.box.center) - o.radius_m;
  }
  std::vector<Eigen::Vector2d> other;
  if (o.shape == ObstacleShape::kBox) {
    for (const Eigen::Vector2d& c : o.box.corners()) other.push_back(c);
  } else {
    other = o.vertices;
  }
  // Work relative to the footprint centre, which keeps the differences small.
  std::vector<Eigen::Vector2d> diff;
  for (const Eigen::Vector2d& p : fp) {
    for (const Eigen::Vector2d& q : other) {
      diff.push_back((p - footprint.center) - (q - footprint.center));
    }
  }
  return signedDistanceToConvex(hullOf(diff), Eigen::Vector2d::Zero());
}

}  // namespace parksim::testing
