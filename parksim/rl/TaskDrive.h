#pragma once
// How a parking task's actions move the robot, one implementation per fidelity
// (ParkingTaskDef.h): DynamicDrive.cpp through sim/episode/Episode.h, KinematicDrive.cpp along exact
// arcs against the collision checker (KinematicCarDrive.cpp for a car: a kinematic bicycle).
// ParkingTask judges what they report; they judge nothing.

#include <cstdint>
#include <memory>
#include <vector>

#include "parksim/core/geometry/Pose2.h"
#include "parksim/core/model/DiffDrive.h"
#include "parksim/core/model/Scenario.h"
#include "parksim/rl/ParkingTaskDef.h"
#include "parksim/rl/TaskSpaces.h"

namespace parksim {

class BulletCollisionWorld;

/// The robot after an action (or a reset), as a fidelity computes it.
struct DriveState {
  Pose2 pose;      ///< true pose
  Pose2 estimate;  ///< the controller's belief (the true pose for the ideal robot)
  Twist twist;     ///< as the controller observes it
  /// A car's front-wheel angle of the bicycle model, rad, left positive (0 for a differential
  /// drive).
  double steer_rad = 0.0;
  double t_s = 0.0;
  /// Obstacles (scenario order, ascending) the chassis penetrated during the action.
  std::vector<int> contacts;
};

class TaskDrive {
 public:
  virtual ~TaskDrive() = default;
  /// Puts the robot at `start`, at rest, time 0; noise_seed seeds the realism's draws.
  virtual void reset(const Pose2& start, std::uint64_t noise_seed, DriveState& out) = 0;
  /// Holds `action` (checked finite; TaskSpaces.h says what it commands) for `steps` physics
  /// steps (the control period).
  virtual void act(const TaskAction& action, long steps, DriveState& out) = 0;
  virtual std::vector<Pose2> obstaclePoses() const = 0;
};

/// The dynamics world through Episode's step API, for at most `max_actions` actions of `steps`
/// physics steps each.
std::unique_ptr<TaskDrive> makeDynamicDrive(const Scenario& scenario, const ParkingTaskDef& def,
                                            long max_actions, long steps);

/// Exact arcs checked against `collision` (kept by reference: it must outlive the drive); for a
/// car, makeKinematicCarDrive's.
std::unique_ptr<TaskDrive> makeKinematicDrive(const Scenario& scenario, const ParkingTaskDef& def,
                                              const BulletCollisionWorld& collision);

/// A car's kinematic bicycle (KinematicCarDrive.cpp), as makeKinematicDrive.
std::unique_ptr<TaskDrive> makeKinematicCarDrive(const Scenario& scenario,
                                                 const ParkingTaskDef& def,
                                                 const BulletCollisionWorld& collision);

}  // namespace parksim
