#include "parksim/rl/TaskSpaces.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "parksim/core/io/Error.h"
#include "parksim/core/io/NumberFormat.h"

namespace parksim {

namespace {

// As the differential drive's, at the car's top speed; its drive never exceeds its speed or
// steering limit, so those bounds are the limits.
TaskObservationBounds carBounds(const Scenario& scenario, double period_s) {
  const RobotDef& r = scenario.robot;
  const double margin = 2.0 * r.max_speed_mps * period_s;
  const LotBounds& lot = scenario.lot;
  const auto x_min = static_cast<float>(lot.x_min_m - margin);
  const auto y_min = static_cast<float>(lot.y_min_m - margin);
  const auto x_max = static_cast<float>(lot.x_max_m + margin);
  const auto y_max = static_cast<float>(lot.y_max_m + margin);
  const auto v = static_cast<float>(r.max_speed_mps);
  const auto steer = static_cast<float>(r.max_steer_rad);
  return {{x_min, y_min, -1.0F, -1.0F, -v, -steer, x_min, y_min, -1.0F, -1.0F},
          {x_max, y_max, 1.0F, 1.0F, v, steer, x_max, y_max, 1.0F, 1.0F}};
}

TaskObservation observation(const Pose2& e, double v, double turn, const Pose2& goal,
                            const TaskObservationBounds& bounds) {
  const std::array<double, kTaskObservationSize> values = {
      e.x,    e.y,    std::cos(e.theta),    std::sin(e.theta),   v, turn,
      goal.x, goal.y, std::cos(goal.theta), std::sin(goal.theta)};
  TaskObservation out{};
  for (std::size_t i = 0; i < kTaskObservationSize; ++i) {
    out[i] = std::clamp(static_cast<float>(values[i]), bounds.low[i], bounds.high[i]);
  }
  return out;
}

}  // namespace

TaskObservationBounds taskObservationBounds(const Scenario& scenario, double period_s) {
  const RobotDef& r = scenario.robot;
  if (r.isCar()) return carBounds(scenario, period_s);
  const double v_max = r.max_wheel_speed_radps * r.wheel_radius_m;
  const double omega_max = 2.0 * v_max / r.wheel_base_m;
  // The reference point is inside the lot when an action starts (else the episode has ended),
  // and one action carries it at most v_max * period.
  const double margin = 2.0 * v_max * period_s;
  const LotBounds& lot = scenario.lot;
  const auto x_min = static_cast<float>(lot.x_min_m - margin);
  const auto y_min = static_cast<float>(lot.y_min_m - margin);
  const auto x_max = static_cast<float>(lot.x_max_m + margin);
  const auto y_max = static_cast<float>(lot.y_max_m + margin);
  const auto v = static_cast<float>(1.5 * v_max);
  const auto omega = static_cast<float>(1.5 * omega_max);
  return {{x_min, y_min, -1.0F, -1.0F, -v, -omega, x_min, y_min, -1.0F, -1.0F},
          {x_max, y_max, 1.0F, 1.0F, v, omega, x_max, y_max, 1.0F, 1.0F}};
}

TaskObservation taskObservation(const Pose2& estimate, const Twist& twist, const Pose2& goal,
                                const TaskObservationBounds& bounds) {
  return observation(estimate, twist.v_mps, twist.omega_radps, goal, bounds);
}

TaskObservation taskCarObservation(const Pose2& estimate, double speed_mps, double steer_rad,
                                   const Pose2& goal, const TaskObservationBounds& bounds) {
  return observation(estimate, speed_mps, steer_rad, goal, bounds);
}

void checkTaskAction(const TaskAction& action, long index) {
  if (std::isfinite(action.left) && std::isfinite(action.right)) return;
  const std::string what = index < 0 ? "action" : "action " + std::to_string(index);
  throw Error(what + ": " + kTaskActionExpected + ", got (" + formatGeneral(action.left) + ", " +
              formatGeneral(action.right) + ")");
}

WheelSpeeds taskWheelSpeeds(const TaskAction& action, const RobotDef& robot) {
  const double max = robot.max_wheel_speed_radps;
  return {std::clamp(action.left, -1.0, 1.0) * max, std::clamp(action.right, -1.0, 1.0) * max};
}

CarCommand taskCarCommand(const TaskAction& action, const RobotDef& robot) {
  CarCommand command;
  command.mode = CarCommand::Mode::kAcceleration;
  command.accel_mps2 = std::clamp(action.left, -1.0, 1.0) * robot.max_accel_mps2;
  command.steer_rad = std::clamp(action.right, -1.0, 1.0) * robot.max_steer_rad;
  return command;
}

}  // namespace parksim
