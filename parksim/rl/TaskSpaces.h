#pragma once
// What a parking task's agent sees and does, defined once: the observation vector and its
// bounds, and how an action becomes wheel speeds. ParkingTask (rl/ParkingTask.h) builds its
// observations and moves its robot with these; so must anything else that runs a policy trained
// on the task (a controller driving an Episode with it), or the policy sees another world.

#include <array>
#include <cstddef>

#include "parksim/core/geometry/Pose2.h"
#include "parksim/core/model/DiffDrive.h"
#include "parksim/core/model/Scenario.h"
#include "parksim/sim/control/Controller.h"

namespace parksim {

/// Size of the observation vector: x, y, cos(theta), sin(theta), v, omega of the robot as the
/// controller sees it, then x, y, cos(theta), sin(theta) of the goal. For a car the sixth value
/// is the steering angle instead of omega (omega = v tan(steer) / axle_distance follows from v
/// and it; the steering angle does not follow from them when the car stands).
inline constexpr std::size_t kTaskObservationSize = 10;

using TaskObservation = std::array<float, kTaskObservationSize>;

/// Bounds of every observation.
struct TaskObservationBounds {
  TaskObservation low{};
  TaskObservation high{};
};

/// The lot grown by what one action of `period_s` can carry the robot past it, doubled for the
/// estimate's error and for pushes (the robot's and the goal's positions: a task may move its
/// goal, and Gymnasium's checker warns of bounds with low == high), [-1, 1] for cos and sin,
/// and 1.5 x the robot's speed limits (overshoot, collisions); a car's speed within its
/// max_speed_mps and its steering angle within max_steer_rad exactly (its drive clips both).
TaskObservationBounds taskObservationBounds(const Scenario& scenario, double period_s);

/// The observation of a robot believed at `estimate` moving at `twist`, with the goal `goal`,
/// clipped into `bounds`.
TaskObservation taskObservation(const Pose2& estimate, const Twist& twist, const Pose2& goal,
                                const TaskObservationBounds& bounds);

/// The observation of a car believed at `estimate` moving at `speed_mps` (negative in
/// reverse) with its front wheels at `steer_rad`, with the goal `goal`, clipped into `bounds`.
TaskObservation taskCarObservation(const Pose2& estimate, double speed_mps, double steer_rad,
                                   const Pose2& goal, const TaskObservationBounds& bounds);

/// An action: two fractions in [-1, 1] (values outside are clipped). A differential drive's
/// are the left and right wheel speeds as fractions of RobotDef::max_wheel_speed_radps; a
/// car's, as highway-env's parking-v0 has them, the acceleration (of max_accel_mps2) and the
/// steering angle's target (of max_steer_rad): `left` is the first, `right` the second.
struct TaskAction {
  double left = 0.0;
  double right = 0.0;
};

/// What every refused action's message says it should have been (after "action: ").
inline constexpr const char* kTaskActionExpected =
    "expected two finite numbers (left, right wheel speed fractions)";

/// Throws Error "action: expected two finite numbers (...), got (l, r)" when a value is not
/// finite; with an index (a batch's task), "action <index>: ...".
void checkTaskAction(const TaskAction& action, long index = -1);

/// The wheel speeds an action commands (fractions clipped into [-1, 1]), rad/s.
WheelSpeeds taskWheelSpeeds(const TaskAction& action, const RobotDef& robot);

/// What an action commands a car (fractions clipped into [-1, 1]): an acceleration
/// (CarCommand::Mode::kAcceleration, action[0] x max_accel_mps2) and the steering angle to
/// steer toward (action[1] x max_steer_rad), which the car reaches at max_steer_rate_radps
/// while the speed changes until it reaches +-max_speed_mps (KinematicCarDrive.cpp).
CarCommand taskCarCommand(const TaskAction& action, const RobotDef& robot);

}  // namespace parksim
