#include "parksim/core/geometry/ConvexPartition.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <unordered_map>

#include "parksim/core/geometry/ExactOrientation.h"
#include "parksim/core/io/Error.h"

namespace parksim {

namespace {

using Points = std::vector<Eigen::Vector2d>;

// Segment vm overlaps the segment from v to q along a line (they share v).
bool runsAlong(const Eigen::Vector2d& v, const Eigen::Vector2d& m, const Eigen::Vector2d& q) {
  return orientation(v, m, q) == 0 && (q - v).dot(m - v) > 0.0;
}

// Segment ab meets edge pq other than at a shared end (where it must not run along the edge).
bool bridgeBlockedBy(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& p,
                     const Eigen::Vector2d& q) {
  const bool shares_a = p == a || q == a;
  const bool shares_b = p == b || q == b;
  if (shares_a || shares_b) {
    if (shares_a && shares_b) return true;  // the same segment
    const Eigen::Vector2d& end = shares_a ? a : b;
    const Eigen::Vector2d& other = shares_a ? b : a;
    const Eigen::Vector2d& far = p == end ? q : p;
    return runsAlong(end, other, far);
  }
  return segmentsMeet(a, b, p, q);
}

// m lies strictly inside the interior angle at v (interior on the left of prev -> v -> next).
bool locallyInside(const Eigen::Vector2d& prev, const Eigen::Vector2d& v,
                   const Eigen::Vector2d& next, const Eigen::Vector2d& m) {
  const int o1 = orientation(prev, v, m);
  const int o2 = orientation(v, next, m);
  if (o1 == 0 || o2 == 0) return false;
  if (orientation(prev, v, next) > 0) return o1 > 0 && o2 > 0;
  return o1 > 0 || o2 > 0;
}

// Joins the holes to the outer ring by bridges: a ring of point indices (a bridge's two ends
// appear twice) whose interior, on its left, is the region.
std::vector<int> bridgedRing(const PolygonWithHoles& region, Points& points) {
  points = region.outer;
  std::vector<int> ring(points.size());
  std::iota(ring.begin(), ring.end(), 0);
  struct Hole {
    int first;
    int size;
    int rightmost;
  };
  std::vector<Hole> holes;
  for (const Points& h : region.holes) {
    Hole hole{static_cast<int>(points.size()), static_cast<int>(h.size()), 0};
    for (int i = 1; i < hole.size; ++i) {
      const Eigen::Vector2d& p = h[static_cast<std::size_t>(i)];
      const Eigen::Vector2d& best = h[static_cast<std::size_t>(hole.rightmost)];
      if (p.x() > best.x() || (p.x() == best.x() && p.y() < best.y())) hole.rightmost = i;
    }
    points.insert(points.end(), h.begin(), h.end());
    holes.push_back(hole);
  }
  // Rightmost holes first: then a hole's rightmost vertex always sees a vertex of the ring so
  // far, past the holes still waiting (which lie to its left).
  std::sort(holes.begin(), holes.end(), [&](const Hole& a, const Hole& b) {
    const Eigen::Vector2d& pa = points[static_cast<std::size_t>(a.first + a.rightmost)];
    const Eigen::Vector2d& pb = points[static_cast<std::size_t>(b.first + b.rightmost)];
    return pa.x() > pb.x() || (pa.x() == pb.x() && a.first < b.first);
  });
  const auto at = [&](int i) -> const Eigen::Vector2d& {
    return points[static_cast<std::size_t>(i)];
  };
  for (std::size_t h = 0; h < holes.size(); ++h) {
    const Hole& hole = holes[h];
    const int m_index = hole.first + hole.rightmost;
    const Eigen::Vector2d& m = at(m_index);
    const int m_prev = hole.first + (hole.rightmost + hole.size - 1) % hole.size;
    const int m_next = hole.first + (hole.rightmost + 1) % hole.size;
    std::vector<std::size_t> order(ring.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    // Nearest first; ties in ring order (std::sort: no temporary buffer to allocate).
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
      const double da = (at(ring[a]) - m).squaredNorm();
      const double db = (at(ring[b]) - m).squaredNorm();
      return da < db || (da == db && a < b);
    });
    const auto free_of = [&](const Eigen::Vector2d& v, const Hole& other) {
      for (int i = 0; i < other.size; ++i) {
        if (bridgeBlockedBy(v, m, at(other.first + i), at(other.first + (i + 1) % other.size))) {
          return false;
        }
      }
      return true;
    };
    bool joined = false;
    for (const std::size_t k : order) {
      const std::size_t n = ring.size();
      const Eigen::Vector2d& v = at(ring[k]);
      if (!locallyInside(at(ring[(k + n - 1) % n]), v, at(ring[(k + 1) % n]), m)) continue;
      if (!locallyInside(at(m_prev), m, at(m_next), v)) continue;
      bool blocked = false;
      for (std::size_t i = 0; i < n && !blocked; ++i) {
        blocked = bridgeBlockedBy(v, m, at(ring[i]), at(ring[(i + 1) % n]));
      }
      for (std::size_t g = h; g < holes.size() && !blocked; ++g) blocked = !free_of(v, holes[g]);
      if (blocked) continue;
      std::vector<int> spliced(ring.begin(), ring.begin() + static_cast<std::ptrdiff_t>(k + 1));
      for (int i = 0; i <= hole.size; ++i) {
        spliced.push_back(hole.first + (hole.rightmost + i) % hole.size);
      }
      spliced.push_back(ring[k]);
      spliced.insert(spliced.end(), ring.begin() + static_cast<std::ptrdiff_t>(k + 1), ring.end());
      ring = std::move(spliced);
      joined = true;
      break;
    }
    if (!joined) throw Error("convex partition: no vertex of the outline sees a hole");
  }
  return ring;
}

struct Triangle {
  int a, b, c;  // ring positions, counter-clockwise
};

// Ear clipping over the ring's positions (a bridge's ends are distinct positions of one point).
std::vector<Triangle> clipEars(const Points& points, const std::vector<int>& ring) {
  const int n = static_cast<int>(ring.size());
  std::vector<int> prev(static_cast<std::size_t>(n));
  std::vector<int> next(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) {
    prev[static_cast<std::size_t>(i)] = (i + n - 1) % n;
    next[static_cast<std::size_t>(i)] = (i + 1) % n;
  }
  const auto pt = [&](int pos) -> const Eigen::Vector2d& {
    return points[static_cast<std::size_t>(ring[static_cast<std::size_t>(pos)])];
  };
  const auto isEar = [&](int v) {
    const int u = prev[static_cast<std::size_t>(v)];
    const int w = next[static_cast<std::size_t>(v)];
    const Eigen::Vector2d& pu = pt(u);
    const Eigen::Vector2d& pv = pt(v);
    const Eigen::Vector2d& pw = pt(w);
    if (orientation(pu, pv, pw) <= 0) return false;
    const double x0 = std::min({pu.x(), pv.x(), pw.x()});
    const double x1 = std::max({pu.x(), pv.x(), pw.x()});
    const double y0 = std::min({pu.y(), pv.y(), pw.y()});
    const double y1 = std::max({pu.y(), pv.y(), pw.y()});
    for (int q = next[static_cast<std::size_t>(w)]; q != u; q = next[static_cast<std::size_t>(q)]) {
      const Eigen::Vector2d& p = pt(q);
      if (p.x() < x0 || p.x() > x1 || p.y() < y0 || p.y() > y1) continue;
      if (p == pu || p == pv || p == pw) continue;
      if (orientation(pu, pv, p) >= 0 && orientation(pv, pw, p) >= 0 &&
          orientation(pw, pu, p) >= 0) {
        return false;
      }
    }
    return true;
  };
  std::vector<Triangle> triangles;
  triangles.reserve(static_cast<std::size_t>(n));
  int left = n;
  int v = 0;
  int misses = 0;
  while (left > 3) {
    if (isEar(v)) {
      const int u = prev[static_cast<std::size_t>(v)];
      const int w = next[static_cast<std::size_t>(v)];
      triangles.push_back({u, v, w});
      next[static_cast<std::size_t>(u)] = w;
      prev[static_cast<std::size_t>(w)] = u;
      --left;
      v = u;
      misses = 0;
      continue;
    }
    v = next[static_cast<std::size_t>(v)];
    if (++misses > left) {
      // No ear left: what remains must be flat (a bridge folded onto itself).
      bool flat = true;
      int q = v;
      for (int i = 0; i < left && flat; ++i, q = next[static_cast<std::size_t>(q)]) {
        flat = orientation(pt(prev[static_cast<std::size_t>(q)]), pt(q),
                           pt(next[static_cast<std::size_t>(q)])) == 0;
      }
      if (!flat) throw Error("convex partition: ear clipping found no ear");
      return triangles;
    }
  }
  const int u = prev[static_cast<std::size_t>(v)];
  const int w = next[static_cast<std::size_t>(v)];
  if (orientation(pt(u), pt(v), pt(w)) > 0) triangles.push_back({u, v, w});
  return triangles;
}

std::uint64_t edgeKey(int a, int b) {
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(a)) << 32) |
         static_cast<std::uint32_t>(b);
}

}  // namespace

std::vector<std::vector<Eigen::Vector2d>> convexPartition(const PolygonWithHoles& input) {
  const PolygonWithHoles region = normalizedRegion(input);
  Points points;
  const std::vector<int> ring = bridgedRing(region, points);
  const std::vector<Triangle> triangles = clipEars(points, ring);
  const auto pt = [&](int pos) -> const Eigen::Vector2d& {
    return points[static_cast<std::size_t>(ring[static_cast<std::size_t>(pos)])];
  };

  // Hertel-Mehlhorn: parts as cycles of ring positions; a diagonal is an edge two parts share
  // in opposite directions (a bridge's two sides are different positions, never shared).
  std::vector<std::vector<int>> parts;
  std::unordered_map<std::uint64_t, int> owner;
  for (const Triangle& t : triangles) {
    const int id = static_cast<int>(parts.size());
    parts.push_back({t.a, t.b, t.c});
    owner[edgeKey(t.a, t.b)] = id;
    owner[edgeKey(t.b, t.c)] = id;
    owner[edgeKey(t.c, t.a)] = id;
  }
  std::vector<std::pair<int, int>> diagonals;
  for (const Triangle& t : triangles) {
    for (const auto& [a, b] : {std::pair{t.a, t.b}, std::pair{t.b, t.c}, std::pair{t.c, t.a}}) {
      if (a < b && owner.count(edgeKey(b, a))) diagonals.emplace_back(a, b);
    }
  }
  std::vector<bool> alive(parts.size(), true);
  for (const auto& [a, b] : diagonals) {
    const int x = owner.at(edgeKey(a, b));
    const int y = owner.at(edgeKey(b, a));
    if (x == y) continue;
    std::vector<int>& px = parts[static_cast<std::size_t>(x)];
    std::vector<int>& py = parts[static_cast<std::size_t>(y)];
    // x as b ... a, y as a ... b.
    std::rotate(px.begin(), std::find(px.begin(), px.end(), b), px.end());
    std::rotate(py.begin(), std::find(py.begin(), py.end(), a), py.end());
    if (px.back() != a || py.back() != b) throw Error("convex partition: broken diagonal");
    const int before_a = px[px.size() - 2];
    const int after_a = py[1];
    const int before_b = py[py.size() - 2];
    const int after_b = px[1];
    if (orientation(pt(before_a), pt(a), pt(after_a)) <= 0 ||
        orientation(pt(before_b), pt(b), pt(after_b)) <= 0) {
      continue;
    }
    owner.erase(edgeKey(a, b));
    owner.erase(edgeKey(b, a));
    for (std::size_t i = 0; i + 1 < py.size(); ++i) {
      if (py[i] == a && py[i + 1] == b) continue;
      owner[edgeKey(py[i], py[i + 1])] = x;
    }
    px.insert(px.end(), py.begin() + 1, py.end() - 1);
    py.clear();
    alive[static_cast<std::size_t>(y)] = false;
  }

  // Areas about the first vertex, so that far-off coordinates do not swamp small parts.
  const Eigen::Vector2d origin = region.outer.front();
  double magnitude = 0.0;
  const auto ringArea = [&](const Points& r) {
    double sum = 0.0;
    for (std::size_t k = 0; k < r.size(); ++k) {
      const Eigen::Vector2d p = r[k] - origin;
      const Eigen::Vector2d q = r[(k + 1) % r.size()] - origin;
      sum += p.x() * q.y() - p.y() * q.x();
      magnitude += std::abs(p.x() * q.y()) + std::abs(p.y() * q.x());
    }
    return sum;
  };
  std::vector<Points> out;
  double area = 0.0;
  for (std::size_t i = 0; i < parts.size(); ++i) {
    if (!alive[i]) continue;
    Points part;
    for (int pos : parts[i]) part.push_back(pt(pos));
    for (std::size_t k = 0; k < part.size(); ++k) {
      const std::size_t n = part.size();
      if (orientation(part[(k + n - 1) % n], part[k], part[(k + 1) % n]) <= 0) {
        throw Error("convex partition: a part is not strictly convex");
      }
    }
    area += ringArea(part);
    out.push_back(std::move(part));
  }
  // The parts' areas add up to the region's (up to the rounding of the sums): nothing is
  // missing and nothing is counted twice.
  double expected = std::abs(ringArea(region.outer));
  for (const Points& hole : region.holes) expected -= std::abs(ringArea(hole));
  if (!(std::abs(area - expected) <= 1e-12 * magnitude)) {
    throw Error("convex partition: the parts do not add up to the polygon");
  }
  return out;
}

}  // namespace parksim
