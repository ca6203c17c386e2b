#pragma once
// Test support: the study's parking lot built in code, and an exact footprint checker by
// separating axes, independent of Bullet.

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

/// Exact footprint checker: separating axes against every obstacle.
class SatChecker final : public FootprintChecker {
 public:
  explicit SatChecker(const Scenario& s) : robot_(s.robot), obstacles_(s.obstacles) {}
  bool isFree(const Pose2& pose, double margin_m = 0.0) const override {
    const OrientedBox fp = footprintAt(robot_, pose, margin_m);
    for (const Obstacle& o : obstacles_) {
      if (boxesOverlap(fp, o.box)) return false;
    }
    return true;
  }

 private:
  RobotDef robot_;
  std::vector<Obstacle> obstacles_;
};

}  // namespace parksim::testing
