#include "parksim/sim/world/ParkedRobotGrid.h"

#include <algorithm>
#include <cmath>

namespace parksim {

ParkedRobotGrid::ParkedRobotGrid(const std::vector<Obstacle>& obstacles, double cell_m)
    : cell_(cell_m) {
  for (std::size_t i = 0; i < obstacles.size(); ++i) {
    if (obstacles[i].kind != ObstacleKind::kParkedRobot) continue;
    const OrientedBox& b = obstacles[i].box;
    const double r = b.half_extents.norm();
    for (std::int64_t cx = index(b.center.x() - r); cx <= index(b.center.x() + r); ++cx) {
      for (std::int64_t cy = index(b.center.y() - r); cy <= index(b.center.y() + r); ++cy) {
        cells_[key(cx, cy)].push_back(static_cast<int>(i));
      }
    }
  }
}

std::vector<int> ParkedRobotGrid::near(const Eigen::Vector2d& p, double reach_m) const {
  std::vector<int> found;
  for (std::int64_t cx = index(p.x() - reach_m); cx <= index(p.x() + reach_m); ++cx) {
    for (std::int64_t cy = index(p.y() - reach_m); cy <= index(p.y() + reach_m); ++cy) {
      const auto it = cells_.find(key(cx, cy));
      if (it != cells_.end()) found.insert(found.end(), it->second.begin(), it->second.end());
    }
  }
  std::sort(found.begin(), found.end());
  found.erase(std::unique(found.begin(), found.end()), found.end());
  return found;
}

std::int64_t ParkedRobotGrid::key(std::int64_t cx, std::int64_t cy) {
  return (cx << 32) ^ (cy & 0xffffffffLL);
}

std::int64_t ParkedRobotGrid::index(double coordinate) const {
  return static_cast<std::int64_t>(std::floor(coordinate / cell_));
}

}  // namespace parksim
