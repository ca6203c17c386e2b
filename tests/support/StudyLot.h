#pragma once
// Test support: the study's parking lot built in code (for the planner, collision and sim tests
// and bench_collision), and an exact footprint checker by separating axes, independent of Bullet.

#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "parksim/core/model/FootprintChecker.h"
#include "parksim/core/model/Geometry.h"
#include "parksim/core/model/Scenario.h"
#include "tests/support/ExactShapes.h"

namespace parksim::testing {

/// Rectangle from its lower-left corner and size, as the study's table gives them.
inline OrientedBox cornerBox(double x, double y, double width, double height) {
  OrientedBox box;
  box.center = {x + 0.5 * width, y + 0.5 * height};
  box.half_extents = {0.5 * width, 0.5 * height};
  return box;
}

inline Obstacle makeObstacle(std::string name, ObstacleKind kind, const OrientedBox& box,
                             double height_m) {
  Obstacle obstacle;
  obstacle.name = std::move(name);
  obstacle.kind = kind;
  obstacle.box = box;
  obstacle.height_m = height_m;
  return obstacle;
}

/// The study's lot (its reference README, rows 1-11, named as in worlds/*.yaml) with the
/// head-in goal.
inline Scenario studyLot() {
  Scenario s;
  s.name = "study_lot";
  const double wall_h = 0.1;
  const double robot_h = s.robot.height_m;
  auto parked = [&](int row, double x, double y, double w, double h) {
    return makeObstacle("robot_" + std::to_string(row), ObstacleKind::kParkedRobot,
                        cornerBox(x, y, w, h), robot_h);
  };
  s.obstacles = {
      makeObstacle("wall_1", ObstacleKind::kWall, cornerBox(0.5, 0.8, 0.1, 0.4), wall_h),
      makeObstacle("wall_2", ObstacleKind::kWall, cornerBox(0.5, 0.0, 0.1, 0.4), wall_h),
      parked(3, 0.700, 0.000, 0.085, 0.080),
      parked(4, 1.000, 0.000, 0.085, 0.080),
      parked(5, 1.300, 0.000, 0.085, 0.080),
      parked(6, 1.600, 0.000, 0.085, 0.080),
      makeObstacle("island_7", ObstacleKind::kIsland, cornerBox(0.8, 0.6, 0.8, 0.1), wall_h),
      parked(8, 0.700, 1.115, 0.080, 0.085),
      parked(9, 1.000, 1.115, 0.080, 0.085),
      parked(10, 1.300, 1.115, 0.080, 0.085),
      parked(11, 1.600, 1.115, 0.080, 0.085),
  };
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

/// Exact footprint checker: separating axes against every box, with the same answers as
/// core's boxesOverlap (touching is free) but each obstacle's axes and extent computed once, so
/// tests can afford many queries; circles and polygons by exactSignedDistance (Minkowski
/// difference, independent of core). Obstacles that pass under the robot are skipped.
class SatChecker final : public FootprintChecker {
 public:
  explicit SatChecker(const Scenario& s) : robot_(s.robot) {
    for (const Obstacle& o : s.obstacles) {
      if (!blocksRobot(o, s.robot)) continue;
      if (o.shape == ObstacleShape::kBox) {
        obstacles_.push_back(Prepared(o.box));
      } else {
        shapes_.push_back(o);
      }
    }
  }

  bool isFree(const Pose2& pose, double margin_m = 0.0) const override {
    const OrientedBox box = footprintAt(robot_, pose, margin_m);
    const Prepared fp(box);
    for (const Prepared& o : obstacles_) {
      if (overlap(fp, o)) return false;
    }
    for (const Obstacle& o : shapes_) {
      // Circumscribed circles apart: free, without the hull.
      if ((o.box.center - box.center).norm() >= fp.radius + o.box.half_extents.norm()) continue;
      if (exactSignedDistance(box, o) < 0.0) return false;
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
  std::vector<Obstacle> shapes_;
};

}  // namespace parksim::testing
