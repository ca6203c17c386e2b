#pragma once
// How far each parked robot has been pushed: the largest and the latest horizontal
// displacement of its centre from where it started. Internal to sim/.

#include <vector>

#include "parksim/core/geometry/Pose2.h"
#include "parksim/core/model/Scenario.h"
#include "parksim/sim/episode/EpisodeMetrics.h"
#include "parksim/sim/world/DynamicsWorld.h"

namespace parksim {

class ParkedDisplacements {
 public:
  /// Every parked robot of `obstacles`, in scenario order; `initial`: every obstacle's pose at
  /// the start (DynamicsWorld::obstaclePoses).
  ParkedDisplacements(const std::vector<Obstacle>& obstacles, std::vector<Pose2> initial);

  /// After a step. Only parked robots that have mass can have moved (the others are fixed
  /// bodies), so far ones cost nothing; positions only, no allocation.
  void update(const DynamicsWorld& world);

  /// Every parked robot, scenario order.
  const std::vector<ParkedRobotDisplacement>& all() const { return parked_; }
  /// The largest displacement of any, m (0 without parked robots).
  double max() const;

 private:
  std::vector<Pose2> initial_;
  std::vector<int> slot_;  // per obstacle: index into parked_, -1 if not a parked robot
  std::vector<ParkedRobotDisplacement> parked_;
};

}  // namespace parksim
