#pragma once
// Parked robots by grid cell, for worlds with too many of them to keep in Bullet from the
// start (SimModelDef::parked_lazy_count): the dynamics world inserts a parked robot only when
// the ego robot comes near, and asks this grid which ones are near. Internal to sim/.

#include <cstdint>
#include <unordered_map>
#include <vector>

#include <Eigen/Core>

#include "parksim/core/model/Scenario.h"

namespace parksim {

class ParkedRobotGrid {
 public:
  /// Lists every parked robot of `obstacles` (scenario index) in each square cell of side
  /// `cell_m` that the circle around its box (through the box's corners) reaches.
  ParkedRobotGrid(const std::vector<Obstacle>& obstacles, double cell_m);

  /// Parked robots listed in the cells that the square `p` +- `reach_m` overlaps: every parked
  /// robot whose box comes within `reach_m` of `p` along x and y, and some farther ones;
  /// ascending scenario indices, each once.
  std::vector<int> near(const Eigen::Vector2d& p, double reach_m) const;

  double cell() const { return cell_; }

 private:
  static std::int64_t key(std::int64_t cx, std::int64_t cy);
  std::int64_t index(double coordinate) const;

  double cell_;
  std::unordered_map<std::int64_t, std::vector<int>> cells_;
};

}  // namespace parksim
