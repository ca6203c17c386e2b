#include "parksim/renders/plots/CSpace.h"

#include <algorithm>
#include <cmath>

#include "parksim/core/geometry/Angle.h"

namespace parksim {

namespace {

double cross(const Eigen::Vector2d& o, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return (a.x() - o.x()) * (b.y() - o.y()) - (a.y() - o.y()) * (b.x() - o.x());
}

}  // namespace

std::vector<Eigen::Vector2d> footprintCornersInRobotFrame(const RobotDef& robot) {
  const double front = robot.front_overhang_m;
  const double back = front - robot.length_m;
  const double half_w = 0.5 * robot.width_m;
  return {{front, -half_w}, {front, half_w}, {back, half_w}, {back, -half_w}};
}

std::vector<Eigen::Vector2d> convexHull(std::vector<Eigen::Vector2d> points) {
  std::sort(points.begin(), points.end(), [](const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
  });
  points.erase(std::unique(points.begin(), points.end()), points.end());
  if (points.size() < 3) return points;
  // Cross products below this count as collinear: the sums carry rounding of ~1e-17 m.
  const double eps = 1e-15;
  std::vector<Eigen::Vector2d> hull(2 * points.size());
  std::size_t k = 0;
  for (const Eigen::Vector2d& p : points) {  // lower hull
    while (k >= 2 && cross(hull[k - 2], hull[k - 1], p) <= eps) --k;
    hull[k++] = p;
  }
  const std::size_t lower = k + 1;
  for (std::size_t i = points.size() - 1; i-- > 0;) {  // upper hull
    while (k >= lower && cross(hull[k - 2], hull[k - 1], points[i]) <= eps) --k;
    hull[k++] = points[i];
  }
  hull.resize(k - 1);  // the last point repeats the first
  return hull;
}

std::vector<Eigen::Vector2d> cspaceSlice(const OrientedBox& obstacle, const RobotDef& robot,
                                         double theta_rad) {
  const double c = std::cos(theta_rad);
  const double s = std::sin(theta_rad);
  std::vector<Eigen::Vector2d> sums;
  sums.reserve(16);
  for (const Eigen::Vector2d& f : footprintCornersInRobotFrame(robot)) {
    const Eigen::Vector2d reflected(-(c * f.x() - s * f.y()), -(s * f.x() + c * f.y()));
    for (const Eigen::Vector2d& o : obstacle.corners()) sums.push_back(o + reflected);
  }
  return convexHull(std::move(sums));
}

std::vector<Eigen::Vector2d> cspaceSlice(const Obstacle& obstacle, const RobotDef& robot,
                                         double theta_rad, int arc_segments) {
  if (obstacle.shape == ObstacleShape::kBox) return cspaceSlice(obstacle.box, robot, theta_rad);
  const double c = std::cos(theta_rad);
  const double s = std::sin(theta_rad);
  std::vector<Eigen::Vector2d> reflected;
  for (const Eigen::Vector2d& f : footprintCornersInRobotFrame(robot)) {
    reflected.emplace_back(-(c * f.x() - s * f.y()), -(s * f.x() + c * f.y()));
  }
  std::vector<Eigen::Vector2d> points;
  if (obstacle.shape == ObstacleShape::kPolygon) {
    for (const Eigen::Vector2d& f : reflected) {
      for (const Eigen::Vector2d& v : obstacle.vertices) points.push_back(v + f);
    }
    return convexHull(std::move(points));
  }
  // Circle: around each corner of the reflected footprint (a rectangle, so each exterior
  // angle is a quarter turn), an arc of the radius between the two edges' outward normals.
  const int n = std::max(1, arc_segments);
  const double r = obstacle.radius_m;
  const Eigen::Vector2d center = obstacle.box.center;
  const std::vector<Eigen::Vector2d> rect = convexHull(reflected);
  const std::size_t m = rect.size();
  for (std::size_t k = 0; k < m; ++k) {
    const Eigen::Vector2d in = rect[k] - rect[(k + m - 1) % m];
    const double a0 = std::atan2(-in.x(), in.y());  // outward normal of the incoming edge
    const Eigen::Vector2d out = rect[(k + 1) % m] - rect[k];
    double a1 = std::atan2(-out.x(), out.y());
    while (a1 < a0) a1 += 2.0 * kPi;
    for (int j = 0; j <= n; ++j) {
      const double a = a0 + (a1 - a0) * j / n;
      points.push_back(center + rect[k] + r * Eigen::Vector2d(std::cos(a), std::sin(a)));
    }
  }
  return convexHull(std::move(points));
}

std::vector<std::vector<Eigen::Vector2d>> cspaceSlices(const Obstacle& obstacle,
                                                       const RobotDef& robot, double theta_rad,
                                                       int arc_segments) {
  if (obstacle.shape != ObstacleShape::kCompound) {
    return {cspaceSlice(obstacle, robot, theta_rad, arc_segments)};
  }
  const double c = std::cos(theta_rad);
  const double s = std::sin(theta_rad);
  std::vector<Eigen::Vector2d> reflected;
  for (const Eigen::Vector2d& f : footprintCornersInRobotFrame(robot)) {
    reflected.emplace_back(-(c * f.x() - s * f.y()), -(s * f.x() + c * f.y()));
  }
  std::vector<std::vector<Eigen::Vector2d>> out;
  out.reserve(obstacle.compound->parts.size());
  for (const std::vector<Eigen::Vector2d>& part : obstacle.compound->parts) {
    std::vector<Eigen::Vector2d> points;
    points.reserve(part.size() * reflected.size());
    for (const Eigen::Vector2d& f : reflected) {
      for (const Eigen::Vector2d& v : part) points.push_back(v + f);
    }
    out.push_back(convexHull(std::move(points)));
  }
  return out;
}

bool insideConvex(const std::vector<Eigen::Vector2d>& polygon, const Eigen::Vector2d& p,
                  double tolerance_m) {
  if (polygon.size() < 3) return false;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const Eigen::Vector2d& a = polygon[i];
    const Eigen::Vector2d& b = polygon[(i + 1) % polygon.size()];
    const double len = (b - a).norm();
    if (cross(a, b, p) / len <= tolerance_m) return false;
  }
  return true;
}

}  // namespace parksim
