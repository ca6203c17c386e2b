#include "parksim/core/model/Geometry.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace parksim {

namespace {

Eigen::Vector2d axisX(double yaw) { return {std::cos(yaw), std::sin(yaw)}; }
Eigen::Vector2d axisY(double yaw) { return {-std::sin(yaw), std::cos(yaw)}; }

// Half-length of the box's projection onto a unit axis.
double projectedRadius(const OrientedBox& b, const BoxAxes& own, const Eigen::Vector2d& axis) {
  return b.half_extents.x() * std::abs(own.x.dot(axis)) +
         b.half_extents.y() * std::abs(own.y.dot(axis));
}

double pointSegmentDistance(const Eigen::Vector2d& p, const Eigen::Vector2d& a,
                            const Eigen::Vector2d& b) {
  const Eigen::Vector2d ab = b - a;
  const double t = std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0);
  return (p - (a + t * ab)).norm();
}

// Closest pair of two disjoint convex polygons always includes a vertex of one of them.
template <typename A, typename B>
double polygonDistance(const A& pa, const B& pb) {
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < pb.size(); ++i) {
    const auto& b0 = pb[i];
    const auto& b1 = pb[(i + 1) % pb.size()];
    for (const auto& a : pa) best = std::min(best, pointSegmentDistance(a, b0, b1));
  }
  for (std::size_t i = 0; i < pa.size(); ++i) {
    const auto& a0 = pa[i];
    const auto& a1 = pa[(i + 1) % pa.size()];
    for (const auto& b : pb) best = std::min(best, pointSegmentDistance(b, a0, a1));
  }
  return best;
}

double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return a.x() * b.y() - a.y() * b.x();
}

}  // namespace

BoxAxes axesOf(double yaw) { return {axisX(yaw), axisY(yaw)}; }
BoxAxes axesOf(const OrientedBox& b) { return axesOf(b.yaw); }

std::array<Eigen::Vector2d, 4> OrientedBox::corners() const {
  const Eigen::Vector2d ex = axisX(yaw) * half_extents.x();
  const Eigen::Vector2d ey = axisY(yaw) * half_extents.y();
  return {center + ex - ey, center + ex + ey, center - ex + ey, center - ex - ey};
}

double separationAlongAxes(const OrientedBox& a, const OrientedBox& b) {
  return separationAlongAxes(a, axesOf(a), b, axesOf(b));
}

double separationAlongAxes(const OrientedBox& a, const BoxAxes& own_a, const OrientedBox& b,
                           const BoxAxes& own_b) {
  const std::array<Eigen::Vector2d, 4> axes = {own_a.x, own_a.y, own_b.x, own_b.y};
  const Eigen::Vector2d d = b.center - a.center;
  double best = -std::numeric_limits<double>::infinity();
  for (const Eigen::Vector2d& axis : axes) {
    const double gap =
        std::abs(d.dot(axis)) - projectedRadius(a, own_a, axis) - projectedRadius(b, own_b, axis);
    best = std::max(best, gap);
  }
  return best;
}

bool boxesOverlap(const OrientedBox& a, const OrientedBox& b) {
  return separationAlongAxes(a, b) < 0.0;
}

double separation(const OrientedBox& a, const Circle& c) {
  // The centre in the box's frame; outside, the distance to the nearest face point; inside,
  // minus the distance to the nearest face.
  const Eigen::Vector2d d = c.center - a.center;
  const double x = std::abs(axisX(a.yaw).dot(d)) - a.half_extents.x();
  const double y = std::abs(axisY(a.yaw).dot(d)) - a.half_extents.y();
  const double outside = std::hypot(std::max(x, 0.0), std::max(y, 0.0));
  const double inside = std::min(std::max(x, y), 0.0);
  return outside + inside - c.radius;
}

double separationAlongAxes(const OrientedBox& a, const std::vector<Eigen::Vector2d>& polygon) {
  return separationAlongAxes(a, axesOf(a), polygon);
}

double separationAlongAxes(const OrientedBox& a, const BoxAxes& own,
                           const std::vector<Eigen::Vector2d>& polygon) {
  const std::size_t n = polygon.size();
  double best = -std::numeric_limits<double>::infinity();
  const auto gapAlong = [&](const Eigen::Vector2d& axis) {
    double lo = std::numeric_limits<double>::infinity();
    double hi = -lo;
    for (const Eigen::Vector2d& p : polygon) {
      const double v = axis.dot(p - a.center);
      lo = std::min(lo, v);
      hi = std::max(hi, v);
    }
    const double r = projectedRadius(a, own, axis);
    return std::max(lo - r, -r - hi);
  };
  best = std::max(best, gapAlong(own.x));
  best = std::max(best, gapAlong(own.y));
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::Vector2d edge = polygon[(i + 1) % n] - polygon[i];
    const double len = edge.norm();
    if (!(len > 0.0)) continue;
    best = std::max(best, gapAlong(Eigen::Vector2d(edge.y() / len, -edge.x() / len)));
  }
  return best;
}

double distance(const OrientedBox& a, const std::vector<Eigen::Vector2d>& polygon) {
  if (separationAlongAxes(a, polygon) <= 0.0) return 0.0;
  return polygonDistance(a.corners(), polygon);
}

double distance(const OrientedBox& a, const OrientedBox& b) {
  if (separationAlongAxes(a, b) <= 0.0) return 0.0;
  return polygonDistance(a.corners(), b.corners());
}

double signedDoubleArea(const std::vector<Eigen::Vector2d>& polygon) {
  double sum = 0.0;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    sum += cross(polygon[i], polygon[(i + 1) % polygon.size()]);
  }
  return sum;
}

bool isStrictlyConvexCcw(const std::vector<Eigen::Vector2d>& polygon) {
  const std::size_t n = polygon.size();
  if (n < 3) return false;
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::Vector2d& a = polygon[i];
    const Eigen::Vector2d& b = polygon[(i + 1) % n];
    const Eigen::Vector2d& c = polygon[(i + 2) % n];
    if (!(cross(b - a, c - b) > 0.0)) return false;
  }
  // Every turn left and the total turning one revolution: the winding number is one.
  double turning = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::Vector2d e0 = polygon[(i + 1) % n] - polygon[i];
    const Eigen::Vector2d e1 = polygon[(i + 2) % n] - polygon[(i + 1) % n];
    turning += std::atan2(cross(e0, e1), e0.dot(e1));
  }
  return std::abs(turning - 2.0 * 3.14159265358979323846) < 1e-6;
}

OrientedBox footprintAt(const RobotDef& robot, const Pose2& pose, double margin_m) {
  const double offset = robot.footprintCenterOffset();
  OrientedBox box;
  box.center = {pose.x + offset * std::cos(pose.theta), pose.y + offset * std::sin(pose.theta)};
  box.half_extents = {0.5 * robot.length_m + margin_m, 0.5 * robot.width_m + margin_m};
  box.yaw = pose.theta;
  return box;
}

double footprintRadius(const RobotDef& robot) {
  const double ahead = robot.front_overhang_m;
  const double behind = robot.length_m - robot.front_overhang_m;
  return std::hypot(std::max(ahead, behind), 0.5 * robot.width_m);
}

}  // namespace parksim
