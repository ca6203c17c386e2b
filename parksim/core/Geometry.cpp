#include "parksim/core/Geometry.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace parksim {

namespace {

Eigen::Vector2d axisX(double yaw) { return {std::cos(yaw), std::sin(yaw)}; }
Eigen::Vector2d axisY(double yaw) { return {-std::sin(yaw), std::cos(yaw)}; }

// Half-length of the box's projection onto a unit axis.
double projectedRadius(const OrientedBox& b, const Eigen::Vector2d& axis) {
  return b.half_extents.x() * std::abs(axisX(b.yaw).dot(axis)) +
         b.half_extents.y() * std::abs(axisY(b.yaw).dot(axis));
}

}  // namespace

std::array<Eigen::Vector2d, 4> OrientedBox::corners() const {
  const Eigen::Vector2d ex = axisX(yaw) * half_extents.x();
  const Eigen::Vector2d ey = axisY(yaw) * half_extents.y();
  return {center + ex - ey, center + ex + ey, center - ex + ey, center - ex - ey};
}

double separationAlongAxes(const OrientedBox& a, const OrientedBox& b) {
  const std::array<Eigen::Vector2d, 4> axes = {axisX(a.yaw), axisY(a.yaw), axisX(b.yaw),
                                               axisY(b.yaw)};
  const Eigen::Vector2d d = b.center - a.center;
  double best = -std::numeric_limits<double>::infinity();
  for (const Eigen::Vector2d& axis : axes) {
    const double gap = std::abs(d.dot(axis)) - projectedRadius(a, axis) - projectedRadius(b, axis);
    best = std::max(best, gap);
  }
  return best;
}

bool boxesOverlap(const OrientedBox& a, const OrientedBox& b) {
  return separationAlongAxes(a, b) < 0.0;
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
