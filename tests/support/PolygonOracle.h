#pragma once
// Test support: whether a footprint overlaps a polygon with holes, decided without parksim's
// geometry (no partition, no separating axes, no Bullet): the footprint's interior meets the
// polygon's exactly when an edge of one properly crosses an edge of the other, or a corner of
// one lies inside the other (by the classic even-odd crossing number). Poses in general position
// (random ones) never touch exactly, so the answer needs no tie rules. Also makes random simple
// polygons with holes (star-shaped rings) for the tests to cut up.

#include <cmath>
#include <random>
#include <vector>

#include <Eigen/Core>

#include "parksim/core/geometry/PolygonRegion.h"
#include "parksim/core/model/Geometry.h"

namespace parksim::testing {

using Ring = std::vector<Eigen::Vector2d>;

/// Even-odd point in polygon over several rings (outline and holes alike).
inline bool insideRings(const std::vector<Ring>& rings, const Eigen::Vector2d& p) {
  bool inside = false;
  for (const Ring& ring : rings) {
    for (std::size_t i = 0, j = ring.size() - 1; i < ring.size(); j = i++) {
      const Eigen::Vector2d& a = ring[i];
      const Eigen::Vector2d& b = ring[j];
      if ((a.y() > p.y()) != (b.y() > p.y()) &&
          p.x() < (b.x() - a.x()) * (p.y() - a.y()) / (b.y() - a.y()) + a.x()) {
        inside = !inside;
      }
    }
  }
  return inside;
}

inline double turnOf(const Eigen::Vector2d& o, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return (a - o).x() * (b - o).y() - (a - o).y() * (b - o).x();
}

inline bool properlyCross(const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                          const Eigen::Vector2d& c, const Eigen::Vector2d& d) {
  return turnOf(a, b, c) * turnOf(a, b, d) < 0.0 && turnOf(c, d, a) * turnOf(c, d, b) < 0.0;
}

/// True when the footprint's interior meets the polygon's (outline and holes in `rings`).
inline bool footprintOverlapsRings(const OrientedBox& footprint, const std::vector<Ring>& rings) {
  const auto corners = footprint.corners();
  const Ring box(corners.begin(), corners.end());
  for (const Eigen::Vector2d& c : box) {
    if (insideRings(rings, c)) return true;
  }
  for (const Ring& ring : rings) {
    for (const Eigen::Vector2d& v : ring) {
      if (insideRings({box}, v)) return true;
    }
    for (std::size_t i = 0; i < ring.size(); ++i) {
      for (std::size_t k = 0; k < 4; ++k) {
        if (properlyCross(ring[i], ring[(i + 1) % ring.size()], box[k], box[(k + 1) % 4])) {
          return true;
        }
      }
    }
  }
  return false;
}

/// A star-shaped ring around `center`: `n` vertices at increasing angles, radii in
/// [r_min, r_max] (simple by construction), counter-clockwise.
inline Ring starRing(std::mt19937_64& rng, const Eigen::Vector2d& center, int n, double r_min,
                     double r_max) {
  std::uniform_real_distribution<double> radius(r_min, r_max);
  std::uniform_real_distribution<double> jitter(0.1, 0.9);
  Ring ring;
  for (int i = 0; i < n; ++i) {
    const double a = 2.0 * 3.14159265358979323846 * (i + jitter(rng)) / n;
    const double r = radius(rng);
    ring.push_back(center + r * Eigen::Vector2d(std::cos(a), std::sin(a)));
  }
  return ring;
}

/// A star-shaped polygon of `n` vertices around `center` (radii 0.35 to 0.95 m) with two
/// star-shaped holes of 5 to 9 vertices, for the 10^5-pose checks.
inline PolygonWithHoles starWithTwoHoles(std::mt19937_64& rng, const Eigen::Vector2d& center,
                                         int n) {
  PolygonWithHoles region;
  region.outer = starRing(rng, center, n, 0.4, 0.9);
  region.holes.push_back(starRing(rng, center + Eigen::Vector2d(0.22, 0.0), 8, 0.05, 0.12));
  region.holes.push_back(starRing(rng, center + Eigen::Vector2d(-0.22, 0.05), 5, 0.04, 0.1));
  return region;
}

}  // namespace parksim::testing
