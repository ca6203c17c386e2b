#include "parksim/renders/scene/SceneClip.h"

#include <algorithm>
#include <cmath>

namespace parksim {

namespace {

bool inside(const Extent2& a, double x, double y) {
  return x >= a.x_min && x <= a.x_max && y >= a.y_min && y <= a.y_max;
}

// The area grown by rounding's reach: content that lies within it is kept exactly as it is.
// Footprints computed to end on the lot's edge (a parked robot's front at y = 0) may end 1e-18 m
// past it; cutting them would change the figure of a world that has nothing outside.
Extent2 withSlack(const Extent2& a) {
  const double e = 1e-9 * std::max({a.width(), a.height(), 1e-3});
  return {a.x_min - e, a.y_min - e, a.x_max + e, a.y_max + e};
}

template <class Points>
bool allInside(const Extent2& slack, const Points& points) {
  return std::all_of(points.begin(), points.end(),
                     [&](const auto& p) { return inside(slack, p.x(), p.y()); });
}

// Points computed on the border are put exactly on it, so the inclusive test accepts them.
Eigen::Vector2d clamped(const Extent2& a, Eigen::Vector2d p) {
  return {std::clamp(p.x(), a.x_min, a.x_max), std::clamp(p.y(), a.y_min, a.y_max)};
}

// The parameter range [t0, t1] of the segment a -> b inside `area` (Liang-Barsky); false when
// none of it is.
bool clipSegment(const Extent2& area, const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                 double& t0, double& t1) {
  const Eigen::Vector2d d = b - a;
  t0 = 0.0;
  t1 = 1.0;
  const double p[4] = {-d.x(), d.x(), -d.y(), d.y()};
  const double q[4] = {a.x() - area.x_min, area.x_max - a.x(), a.y() - area.y_min,
                       area.y_max - a.y()};
  for (int k = 0; k < 4; ++k) {
    if (p[k] == 0.0) {
      if (q[k] < 0.0) return false;  // parallel to this border and beyond it
      continue;
    }
    const double r = q[k] / p[k];
    if (p[k] < 0.0) {
      t0 = std::max(t0, r);
    } else {
      t1 = std::min(t1, r);
    }
    if (t0 > t1) return false;
  }
  return true;
}

// One Sutherland-Hodgman pass: keeps the side of the line `coord(p) = bound` where
// `keep_above` says, inclusive.
std::vector<Eigen::Vector2d> clipHalfPlane(const std::vector<Eigen::Vector2d>& in, int coord,
                                           double bound, bool keep_above) {
  std::vector<Eigen::Vector2d> out;
  if (in.empty()) return out;
  auto kept = [&](const Eigen::Vector2d& p) {
    return keep_above ? p[coord] >= bound : p[coord] <= bound;
  };
  for (std::size_t i = 0; i < in.size(); ++i) {
    const Eigen::Vector2d& prev = in[(i + in.size() - 1) % in.size()];
    const Eigen::Vector2d& cur = in[i];
    const bool cur_in = kept(cur);
    if (cur_in != kept(prev)) {
      const double t = (bound - prev[coord]) / (cur[coord] - prev[coord]);
      Eigen::Vector2d x = prev + t * (cur - prev);
      x[coord] = bound;
      out.push_back(x);
    }
    if (cur_in) out.push_back(cur);
  }
  return out;
}

}  // namespace

std::vector<Eigen::Vector2d> clipPolygon(const std::vector<Eigen::Vector2d>& polygon,
                                         const Extent2& area) {
  if (polygon.size() >= 3 && allInside(withSlack(area), polygon)) return polygon;
  std::vector<Eigen::Vector2d> p = clipHalfPlane(polygon, 0, area.x_min, true);
  p = clipHalfPlane(p, 0, area.x_max, false);
  p = clipHalfPlane(p, 1, area.y_min, true);
  p = clipHalfPlane(p, 1, area.y_max, false);
  for (Eigen::Vector2d& q : p) q = clamped(area, q);
  // A vertex on the border comes out twice (itself and the crossing at it).
  p.erase(std::unique(p.begin(), p.end()), p.end());
  while (p.size() > 1 && p.front() == p.back()) p.pop_back();
  if (p.size() < 3) return {};
  // A polygon touching the area from outside leaves a sliver along the border: no area. Judged
  // against its own bounding box, so small obstacles in a large lot are kept.
  Eigen::Vector2d lo = p.front();
  Eigen::Vector2d hi = p.front();
  double twice_area = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Eigen::Vector2d& a = p[i];
    const Eigen::Vector2d& b = p[(i + 1) % p.size()];
    twice_area += a.x() * b.y() - b.x() * a.y();
    lo = lo.cwiseMin(a);
    hi = hi.cwiseMax(a);
  }
  const double box = (hi.x() - lo.x()) * (hi.y() - lo.y());
  if (box <= 0.0 || std::abs(twice_area) <= 1e-12 * box) return {};
  return p;
}

std::vector<ScenePolyline> clipPolyline(const ScenePolyline& line, const Extent2& area) {
  const std::vector<Eigen::Vector3d>& pts = line.points;
  if (allInside(withSlack(area), pts)) return {line};
  if (pts.size() < 2) return {};  // a lone point outside
  std::vector<ScenePolyline> pieces;
  const std::size_t n = pts.size();
  const std::size_t segments = line.closed && n > 2 ? n : n - 1;
  bool continues = false;       // the last piece ends at the end of the previous segment
  bool first_at_start = false;  // the first piece begins at the line's first point
  auto at = [&](const Eigen::Vector3d& a, const Eigen::Vector3d& b, double t) {
    if (t == 0.0) return a;
    if (t == 1.0) return b;
    const Eigen::Vector3d p = a + t * (b - a);
    const Eigen::Vector2d xy = clamped(area, p.head<2>());
    return Eigen::Vector3d(xy.x(), xy.y(), p.z());
  };
  for (std::size_t i = 0; i < segments; ++i) {
    const Eigen::Vector3d& a = pts[i];
    const Eigen::Vector3d& b = pts[(i + 1) % n];
    double t0 = 0.0;
    double t1 = 1.0;
    if (!clipSegment(area, a.head<2>(), b.head<2>(), t0, t1)) {
      continues = false;
      continue;
    }
    if (!(continues && t0 == 0.0)) {
      if (pieces.empty()) first_at_start = i == 0 && t0 == 0.0;
      pieces.push_back({{at(a, b, t0)}, line.color, line.width_px, false});
    }
    pieces.back().points.push_back(at(a, b, t1));
    continues = t1 == 1.0;
  }
  // A closed line's last piece runs on into its first one through the first point.
  if (line.closed && n > 2 && continues && first_at_start && pieces.size() >= 2) {
    ScenePolyline& last = pieces.back();
    last.points.insert(last.points.end(), pieces.front().points.begin() + 1,
                       pieces.front().points.end());
    pieces.front() = std::move(last);
    pieces.pop_back();
  }
  // A segment that only grazes a corner leaves a piece of no length.
  std::erase_if(pieces, [](const ScenePolyline& piece) {
    return std::all_of(piece.points.begin(), piece.points.end(),
                       [&](const Eigen::Vector3d& p) { return p == piece.points.front(); });
  });
  return pieces;
}

void clipToArea(Scene& scene, const Extent2& area) {
  const Extent2 slack = withSlack(area);
  std::vector<ScenePolygon> polygons;
  for (ScenePolygon& p : scene.polygons) {
    p.points = clipPolygon(p.points, area);
    if (!p.points.empty()) polygons.push_back(std::move(p));
  }
  scene.polygons = std::move(polygons);

  std::vector<ScenePrism> prisms;
  for (ScenePrism& p : scene.prisms) {
    p.footprint = clipPolygon(p.footprint, area);
    if (!p.footprint.empty()) prisms.push_back(std::move(p));
  }
  std::vector<SceneBox> boxes;
  for (const SceneBox& b : scene.boxes) {
    const auto corners = b.footprint.corners();
    if (allInside(slack, corners)) {
      boxes.push_back(b);
      continue;
    }
    std::vector<Eigen::Vector2d> footprint =
        clipPolygon(std::vector<Eigen::Vector2d>(corners.begin(), corners.end()), area);
    if (!footprint.empty())
      prisms.push_back({std::move(footprint), b.z_min_m, b.height_m, b.color});
  }
  scene.boxes = std::move(boxes);
  scene.prisms = std::move(prisms);

  std::vector<ScenePolyline> lines;
  for (const ScenePolyline& line : scene.lines) {
    if (line.points.size() < 2) {
      if (!line.points.empty() && inside(slack, line.points[0].x(), line.points[0].y())) {
        lines.push_back(line);
      }
      continue;
    }
    for (ScenePolyline& piece : clipPolyline(line, area)) lines.push_back(std::move(piece));
  }
  scene.lines = std::move(lines);

  std::vector<SceneArrow> arrows;
  for (SceneArrow arrow : scene.arrows) {
    const Eigen::Vector2d tail(arrow.pose.x, arrow.pose.y);
    if (!inside(slack, tail.x(), tail.y())) continue;
    const Eigen::Vector2d tip = tail + arrow.length_m * Eigen::Vector2d(std::cos(arrow.pose.theta),
                                                                        std::sin(arrow.pose.theta));
    double t0 = 0.0;
    double t1 = 1.0;
    if (!inside(slack, tip.x(), tip.y()) && clipSegment(area, tail, tip, t0, t1)) {
      arrow.length_m *= t1;
      arrow.head_m *= t1;
    }
    if (arrow.length_m > 0.0) arrows.push_back(arrow);
  }
  scene.arrows = std::move(arrows);

  std::erase_if(scene.texts, [&](const SceneText& text) {
    return text.world && !inside(slack, text.world->x(), text.world->y());
  });
}

}  // namespace parksim
