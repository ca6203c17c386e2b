#pragma once
// The plan as a function of time, exactly as the planner defines it: each point's wheel speeds
// are held from its time until the next point's, and the pose in between is their exact
// integral (integrateExact) from the point's pose. Before the first point the reference is the
// first pose; after the last, the last pose with zero speeds.

#include "parksim/core/geometry/Pose2.h"
#include "parksim/core/model/DiffDrive.h"
#include "parksim/core/model/RobotDef.h"
#include "parksim/core/model/Trajectory.h"

namespace parksim {

class ReferenceTrajectory {
 public:
  /// Keeps a copy of `plan`. Throws Error when it is empty or its times do not increase.
  ReferenceTrajectory(const Trajectory& plan, const RobotDef& robot);

  /// Time of the first and last point, s (the plan's clock).
  double startTime() const;
  double endTime() const;

  /// Pose at plan time t_s.
  Pose2 poseAt(double t_s) const;
  /// Wheel speeds held at plan time t_s (zero outside the plan).
  WheelSpeeds wheelsAt(double t_s) const;
  /// Body twist held at plan time t_s.
  Twist twistAt(double t_s) const;
  /// A car's steering angle held at plan time t_s (TrajectoryPoint::steer_rad): the first
  /// point's before the start, the last point's from its time on, rad.
  double steerAt(double t_s) const;
  /// The angle a steering turning at most robot.max_steer_rate_radps aims at, at plan time t_s,
  /// to follow the plan's held angles with every change centred on the time the new angle is
  /// held from: the next point's angle from |change| / (2 rate) before that point's time, rad.
  /// Turning through the change at the rate from there, the steering's curvature integrates to
  /// the plan's over the change (the path's heading matches once it is done).
  double steerTargetAt(double t_s) const;

  const Trajectory& plan() const { return plan_; }

 private:
  /// Index of the point whose period contains t_s, or -1 before the start, or the last index
  /// at or after the end.
  long segmentAt(double t_s) const;

  Trajectory plan_;
  RobotDef robot_;
};

}  // namespace parksim
