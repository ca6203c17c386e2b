#pragma once
// Test support: the study's parking lot built in code, and an exact footprint checker by
// separating axes, independent of Bullet.

#include <cmath>
#include <vector>

#include "core/FootprintChecker.h"
#include "core/Geometry.h"
#include "core/Scenario.h"

namespace parksim::testing {

/// The study's lot (shared/reference/README.md) with the head-in goal.
inline Scenario studyLot() {
  Scenario s;
  s.name = "study_lot";
  struct Rect {
    double x, y, w, h;
    ObstacleKind kind;
  };
  const Rect rects[] = {
      {0.500, 0.800, 0.100, 0.400, ObstacleKind::kWall},
      {0.500, 0.000, 0.100, 0.400, ObstacleKind::kWall},
      {0.700, 0.000, 0.085, 0.080, ObstacleKind::kParkedRobot},
      {1.000, 0.000, 0.085, 0.080, ObstacleKind::kParkedRobot},
      {1.300, 0.000, 0.085, 0.080, ObstacleKind::kParkedRobot},
      {1.600, 0.000, 0.085, 0.080, ObstacleKind::kParkedRobot},
      {0.800, 0.600, 0.800, 0.100, ObstacleKind::kIsland},
      {0.700, 1.115, 0.080, 0.085, ObstacleKind::kParkedRobot},
      {1.000, 1.115, 0.080, 0.085, ObstacleKind::kParkedRobot},
      {1.300, 1.115, 0.080, 0.085, ObstacleKind::kParkedRobot},
      {1.600, 1.115, 0.080, 0.085, ObstacleKind::kParkedRobot},
  };
  int i = 1;
  for (const Rect& r : rects) {
    Obstacle o;
    o.name = "obstacle_" + std::to_string(i++);
    o.kind = r.kind;
    o.box.center = {r.x + 0.5 * r.w, r.y + 0.5 * r.h};
    o.box.half_extents = {0.5 * r.w, 0.5 * r.h};
    s.obstacles.push_back(o);
  }
  s.start = {0.1, 0.1, degToRad(90)};
  s.goal.pose = {1.5, 0.04, degToRad(-90)};
  return s;
}

/// The parallel-parking variant of the study's lot.
inline Scenario studyLotParallel() {
  Scenario s = studyLot();
  s.goal.pose = {1.2, 1.16, 0.0};
  return s;
}

/// Exact footprint checker: separating axes against every obstacle, with the same answers as
/// core's boxesOverlap (touching is free) but each obstacle's axes and extent computed once, so
/// tests can afford many queries.
class SatChecker final : public FootprintChecker {
 public:
  explicit SatChecker(const Scenario& s) : robot_(s.robot) {
    for (const Obstacle& o : s.obstacles) obstacles_.push_back(Prepared(o.box));
  }

  bool isFree(const Pose2& pose, double margin_m = 0.0) const override {
    const Prepared fp(footprintAt(robot_, pose, margin_m));
    for (const Prepared& o : obstacles_) {
      if (overlap(fp, o)) return false;
    }
    return true;
  }

 private:
  struct Prepared {
    explicit Prepared(const OrientedBox& b)
        : center(b.center),
          half(b.half_extents),
          axis_x(std::cos(b.yaw), std::sin(b.yaw)),
          axis_y(-std::sin(b.yaw), std::cos(b.yaw)),
          radius(b.half_extents.norm()) {}
    double projectedRadius(const Eigen::Vector2d& axis) const {
      return half.x() * std::abs(axis_x.dot(axis)) + half.y() * std::abs(axis_y.dot(axis));
    }
    Eigen::Vector2d center, half, axis_x, axis_y;
    double radius;  // of the circumscribed circle
  };

  // Overlap with positive area: the projections overlap on all four candidate axes.
  static bool overlap(const Prepared& a, const Prepared& b) {
    const Eigen::Vector2d d = b.center - a.center;
    if (d.norm() >= a.radius + b.radius) return false;  // circumscribed circles apart
    for (const Eigen::Vector2d* axis : {&a.axis_x, &a.axis_y, &b.axis_x, &b.axis_y}) {
      if (std::abs(d.dot(*axis)) - a.projectedRadius(*axis) - b.projectedRadius(*axis) >= 0.0) {
        return false;
      }
    }
    return true;
  }

  RobotDef robot_;
  std::vector<Prepared> obstacles_;
};

}  // namespace parksim::testing
