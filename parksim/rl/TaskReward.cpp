#include "parksim/rl/TaskReward.h"

#include <cmath>

#include "parksim/core/geometry/Angle.h"

namespace parksim {

double taskGoalDistance(const ParkingTaskDef& def, double pos_err_m, double heading_err_rad) {
  return std::sqrt(pos_err_m / def.distance_scale_m + def.heading_weight * heading_err_rad / kPi);
}

double taskPotential(const ParkingTaskDef& def, double pos_err_m, double heading_err_rad) {
  return -def.shaping_weight * taskGoalDistance(def, pos_err_m, heading_err_rad);
}

TaskOutcome taskOutcome(const ParkingTaskDef& def, const GoalRegion& goal, const LotBounds& lot,
                        const Pose2& pose, bool contact) {
  TaskOutcome outcome;
  outcome.success = positionDistance(pose, goal.pose) <= def.success_position_m &&
                    goalHeadingError(goal, pose.theta) <= def.success_heading_rad && !contact;
  outcome.contact = contact;
  outcome.exit = !lot.contains(pose.x, pose.y);
  outcome.terminated =
      outcome.success || outcome.exit || (outcome.contact && def.terminate_on_contact);
  return outcome;
}

double taskReward(const ParkingTaskDef& def, double before, double after,
                  const TaskOutcome& outcome) {
  // A terminal state's potential is 0: the telescoping sum then ends at -phi(s_0).
  double reward = (outcome.terminated ? 0.0 : def.discount * after) - before;
  if (outcome.success) reward += def.success_reward;
  if (outcome.contact) reward += def.contact_reward;
  if (outcome.exit) reward += def.exit_reward;
  return reward;
}

}  // namespace parksim

namespace parksim {

double taskTransitionReward(const ParkingTaskDef& def, const GoalRegion& goal, const LotBounds& lot,
                            const Pose2& before, const Pose2& after, bool contact) {
  const auto potential = [&](const Pose2& p) {
    return taskPotential(def, positionDistance(p, goal.pose), goalHeadingError(goal, p.theta));
  };
  return taskReward(def, potential(before), potential(after),
                    taskOutcome(def, goal, lot, after, contact));
}

}  // namespace parksim
