#pragma once
// What both kinematic drives share (KinematicDrive.cpp, KinematicCarDrive.cpp): the footprint
// moved along one exact arc (integrateExact) against the planner's collision checker, checked
// so densely that no point of it moves more than kinematic_check_m between two checks.

#include <string>
#include <unordered_map>
#include <vector>

#include "parksim/core/geometry/Pose2.h"
#include "parksim/core/model/DiffDrive.h"
#include "parksim/core/model/Scenario.h"
#include "parksim/rl/ParkingTaskDef.h"

namespace parksim {

class BulletCollisionWorld;

class KinematicSweep {
 public:
  KinematicSweep(const Scenario& scenario, const ParkingTaskDef& def,
                 const BulletCollisionWorld& collision);

  /// Moves from `from` along `twist` for `duration_s`: the end pose when every check is free,
  /// else the last free pose before the first penetrating one, whose overlapping obstacles
  /// (scenario indices, sorted) are appended to `contacts`.
  Pose2 move(const Pose2& from, const Twist& twist, double duration_s,
             std::vector<int>& contacts) const;

  /// Every obstacle's pose, in the scenario's order (fixed: kinematic obstacles never move).
  const std::vector<Pose2>& obstaclePoses() const { return obstacles_; }

 private:
  double check_m_;
  double radius_m_;
  const BulletCollisionWorld& collision_;
  std::unordered_map<std::string, int> index_;  // obstacle name -> scenario index
  std::vector<Pose2> obstacles_;
};

}  // namespace parksim
