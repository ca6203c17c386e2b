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

namespace parksim {

/// Size of the observation vector: x, y, cos(theta), sin(theta), v, omega of the robot as the
/// controller sees it, then x, y, cos(theta), sin(theta) of the goal.
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
/// and 1.5 x the robot's speed limits (overshoot, collisions).
TaskObservationBounds taskObservationBounds(const Scenario& scenario, double period_s);

/// The observation of a robot believed at `estimate` moving at `twist`, with the goal `goal`,
/// clipped into `bounds`.
TaskObservation taskObservation(const Pose2& estimate, const Twist& twist, const Pose2& goal,
                                const TaskObservationBounds& bounds);

/// An action: the left and right wheel speeds as fractions of RobotDef::max_wheel_speed_radps;
/// values outside [-1, 1] are clipped.
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

}  // namespace parksim
