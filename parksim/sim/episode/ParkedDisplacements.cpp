#include "parksim/sim/episode/ParkedDisplacements.h"

#include <algorithm>
#include <utility>

namespace parksim {

ParkedDisplacements::ParkedDisplacements(const std::vector<Obstacle>& obstacles,
                                         std::vector<Pose2> initial)
    : initial_(std::move(initial)), slot_(obstacles.size(), -1) {
  for (std::size_t i = 0; i < obstacles.size(); ++i) {
    if (obstacles[i].kind != ObstacleKind::kParkedRobot) continue;
    slot_[i] = static_cast<int>(parked_.size());
    parked_.push_back({obstacles[i].name, 0.0, 0.0});
  }
}

void ParkedDisplacements::update(const DynamicsWorld& world) {
  for (int index : world.movableObstacles()) {
    const auto i = static_cast<std::size_t>(index);
    const Eigen::Vector2d p = world.obstaclePosition(i);
    const double d = positionDistance({p.x(), p.y(), 0.0}, initial_[i]);
    ParkedRobotDisplacement& slot = parked_[static_cast<std::size_t>(slot_[i])];
    slot.final_m = d;
    slot.max_m = std::max(slot.max_m, d);
  }
}

double ParkedDisplacements::max() const {
  double out = 0.0;
  for (const ParkedRobotDisplacement& p : parked_) out = std::max(out, p.max_m);
  return out;
}

}  // namespace parksim
