#include "parksim/core/geometry/PolygonRegion.h"

#include <algorithm>
#include <cmath>
#include <functional>

#include "parksim/core/geometry/ExactOrientation.h"

namespace parksim {

namespace {

std::string regionRingName(std::size_t ring) {
  return ring == 0 ? std::string("the outline") : "hole " + std::to_string(ring - 1);
}

// p lies on segment ab, given that the three are collinear.
bool onCollinearSegment(const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                        const Eigen::Vector2d& p) {
  return std::min(a.x(), b.x()) <= p.x() && p.x() <= std::max(a.x(), b.x()) &&
         std::min(a.y(), b.y()) <= p.y() && p.y() <= std::max(a.y(), b.y());
}

// Crossing number of a ray from p toward +x over one ring; boundary points set `on`.
int rayCrossings(const std::vector<Eigen::Vector2d>& ring, const Eigen::Vector2d& p, bool& on) {
  int count = 0;
  const std::size_t n = ring.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::Vector2d& a = ring[i];
    const Eigen::Vector2d& b = ring[(i + 1) % n];
    const int turn = orientation(a, b, p);
    if (turn == 0 && onCollinearSegment(a, b, p)) on = true;
    if ((a.y() > p.y()) == (b.y() > p.y())) continue;
    // The edge crosses p's height; it crosses the ray when p lies to its left going up (to its
    // right going down).
    if ((b.y() > a.y()) ? turn > 0 : turn < 0) ++count;
  }
  return count;
}

bool insideRing(const std::vector<Eigen::Vector2d>& ring, const Eigen::Vector2d& p, bool& on) {
  return rayCrossings(ring, p, on) % 2 == 1;
}

struct RegionEdge {
  double x_min, x_max, y_min, y_max;
  std::size_t ring;
  std::size_t index;  // edge from vertex index to index + 1
};

}  // namespace

bool segmentsMeet(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c,
                  const Eigen::Vector2d& d) {
  const int o1 = orientation(a, b, c);
  const int o2 = orientation(a, b, d);
  const int o3 = orientation(c, d, a);
  const int o4 = orientation(c, d, b);
  if (o1 * o2 < 0 && o3 * o4 < 0) return true;  // a proper crossing
  // Otherwise they meet only where an end of one lies on the other.
  if (o1 == 0 && onCollinearSegment(a, b, c)) return true;
  if (o2 == 0 && onCollinearSegment(a, b, d)) return true;
  if (o3 == 0 && onCollinearSegment(c, d, a)) return true;
  if (o4 == 0 && onCollinearSegment(c, d, b)) return true;
  return false;
}

namespace {

// Each ring simple, no two meeting; `ringName` names them in the words.
std::optional<std::string> ringsMeetProblem(
    const std::vector<const std::vector<Eigen::Vector2d>*>& rings,
    const std::function<std::string(std::size_t)>& name_of) {
  std::size_t total = 0;
  for (std::size_t r = 0; r < rings.size(); ++r) {
    const std::vector<Eigen::Vector2d>& ring = *rings[r];
    total += ring.size();
    if (ring.size() < 3) {
      return name_of(r) + " has " + std::to_string(ring.size()) +
             " vertices; a polygon needs at least 3";
    }
    for (std::size_t i = 0; i < ring.size(); ++i) {
      if (!ring[i].allFinite()) {
        return name_of(r) + ", vertex " + std::to_string(i) + ": not a finite point";
      }
    }
    bool flat = true;
    for (std::size_t i = 2; i < ring.size() && flat; ++i) {
      flat = orientation(ring[0], ring[1], ring[i]) == 0;
    }
    if (flat) return name_of(r) + " has no area: its vertices lie on one line";
  }
  if (total > kMaxPolygonRegionVertices) {
    return "has " + std::to_string(total) + " vertices; a polygon may have at most " +
           std::to_string(kMaxPolygonRegionVertices) + " (holes included; docs/limits.md)";
  }

  // Every pair of edges whose bounding boxes meet, found by a sweep along x; neighbours in a
  // ring may share only their common end.
  std::vector<RegionEdge> segments;
  segments.reserve(total);
  for (std::size_t r = 0; r < rings.size(); ++r) {
    const std::vector<Eigen::Vector2d>& ring = *rings[r];
    for (std::size_t i = 0; i < ring.size(); ++i) {
      const Eigen::Vector2d& a = ring[i];
      const Eigen::Vector2d& b = ring[(i + 1) % ring.size()];
      if (a == b) {
        return name_of(r) + ", vertex " + std::to_string((i + 1) % ring.size()) +
               ": repeats the vertex before it";
      }
      segments.push_back({std::min(a.x(), b.x()), std::max(a.x(), b.x()), std::min(a.y(), b.y()),
                          std::max(a.y(), b.y()), r, i});
    }
  }
  std::sort(segments.begin(), segments.end(),
            [](const RegionEdge& s, const RegionEdge& t) { return s.x_min < t.x_min; });
  for (std::size_t i = 0; i < segments.size(); ++i) {
    const RegionEdge& s = segments[i];
    const std::vector<Eigen::Vector2d>& rs = *rings[s.ring];
    const Eigen::Vector2d& a = rs[s.index];
    const Eigen::Vector2d& b = rs[(s.index + 1) % rs.size()];
    for (std::size_t j = i + 1; j < segments.size() && segments[j].x_min <= s.x_max; ++j) {
      const RegionEdge& t = segments[j];
      if (t.y_min > s.y_max || t.y_max < s.y_min) continue;
      const std::vector<Eigen::Vector2d>& rt = *rings[t.ring];
      const Eigen::Vector2d& c = rt[t.index];
      const Eigen::Vector2d& d = rt[(t.index + 1) % rt.size()];
      if (s.ring == t.ring) {
        const std::size_t n = rs.size();
        const bool next = (s.index + 1) % n == t.index;
        const bool prev = (t.index + 1) % n == s.index;
        if (next || prev) {
          // Neighbours: they meet at the shared vertex; anything more is a spike folding back.
          const Eigen::Vector2d& shared = next ? b : a;
          const Eigen::Vector2d& far_s = next ? a : b;
          const Eigen::Vector2d& far_t = next ? d : c;
          if (orientation(far_s, shared, far_t) == 0 &&
              (far_t - shared).dot(far_s - shared) > 0.0) {
            return name_of(s.ring) + ", vertex " + std::to_string(next ? t.index : s.index) +
                   ": the outline folds back on itself there";
          }
          continue;
        }
      }
      if (segmentsMeet(a, b, c, d)) {
        if (s.ring == t.ring) {
          return name_of(s.ring) + " crosses or touches itself (edges from vertex " +
                 std::to_string(std::min(s.index, t.index)) + " and vertex " +
                 std::to_string(std::max(s.index, t.index)) + "): a polygon must be simple";
        }
        return name_of(std::min(s.ring, t.ring)) + " and " + name_of(std::max(s.ring, t.ring)) +
               " cross or touch each other";
      }
    }
  }
  return std::nullopt;
}

}  // namespace

std::optional<std::string> ringsProblem(const std::vector<std::vector<Eigen::Vector2d>>& rings) {
  std::vector<const std::vector<Eigen::Vector2d>*> pointers;
  for (const auto& ring : rings) pointers.push_back(&ring);
  return ringsMeetProblem(pointers, [](std::size_t r) { return "subpath " + std::to_string(r); });
}

std::optional<std::string> regionProblem(const PolygonWithHoles& region) {
  std::vector<const std::vector<Eigen::Vector2d>*> rings{&region.outer};
  for (const auto& hole : region.holes) rings.push_back(&hole);
  if (auto problem = ringsMeetProblem(rings, regionRingName)) return problem;
  // No edges meet: each hole lies wholly inside or outside each other ring; one vertex tells.
  for (std::size_t h = 1; h < rings.size(); ++h) {
    bool on = false;
    if (!insideRing(region.outer, rings[h]->front(), on)) {
      return regionRingName(h) + " lies outside the outline";
    }
    for (std::size_t k = 1; k < rings.size(); ++k) {
      if (k != h && insideRing(*rings[k], rings[h]->front(), on)) {
        return regionRingName(h) + " lies inside " + regionRingName(k) + "; holes may not nest";
      }
    }
  }
  return std::nullopt;
}

namespace {

double ringDoubleArea(const std::vector<Eigen::Vector2d>& ring) {
  double sum = 0.0;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const Eigen::Vector2d& a = ring[i];
    const Eigen::Vector2d& b = ring[(i + 1) % ring.size()];
    sum += a.x() * b.y() - a.y() * b.x();
  }
  return sum;
}

// Drops vertices on the line between their neighbours, until none is left; then winds the ring
// counter-clockwise (or clockwise).
std::vector<Eigen::Vector2d> tidyRing(std::vector<Eigen::Vector2d> ring, bool ccw) {
  bool dropped = true;
  while (dropped && ring.size() > 3) {
    dropped = false;
    for (std::size_t i = 0; i < ring.size() && ring.size() > 3; ++i) {
      const std::size_t n = ring.size();
      if (orientation(ring[(i + n - 1) % n], ring[i], ring[(i + 1) % n]) == 0) {
        ring.erase(ring.begin() + static_cast<std::ptrdiff_t>(i));
        dropped = true;
        --i;
      }
    }
  }
  // Reversed after the first vertex, which stays first.
  if ((ringDoubleArea(ring) > 0.0) != ccw) std::reverse(ring.begin() + 1, ring.end());
  return ring;
}

}  // namespace

PolygonWithHoles normalizedRegion(const PolygonWithHoles& region) {
  PolygonWithHoles out;
  out.outer = tidyRing(region.outer, true);
  for (const auto& hole : region.holes) out.holes.push_back(tidyRing(hole, false));
  return out;
}

double regionDoubleArea(const PolygonWithHoles& region) {
  double area = std::abs(ringDoubleArea(region.outer));
  for (const auto& hole : region.holes) area -= std::abs(ringDoubleArea(hole));
  return area;
}

bool insideRegion(const PolygonWithHoles& region, const Eigen::Vector2d& p) {
  bool on = false;
  const bool in_outer = insideRing(region.outer, p, on);
  if (on) return true;
  if (!in_outer) return false;
  for (const auto& hole : region.holes) {
    const bool in_hole = insideRing(hole, p, on);
    if (on) return true;
    if (in_hole) return false;
  }
  return true;
}

}  // namespace parksim
