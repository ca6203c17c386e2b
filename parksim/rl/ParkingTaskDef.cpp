#include "parksim/rl/ParkingTaskDef.h"

#include <cmath>

#include "parksim/core/io/Error.h"
#include "parksim/core/io/NumberFormat.h"

namespace parksim {

const char* toString(TaskFidelity fidelity) {
  switch (fidelity) {
    case TaskFidelity::kDynamics: return "dynamics";
    case TaskFidelity::kKinematic: return "kinematic";
  }
  return "dynamics";
}

TaskFidelity taskFidelityFromString(const std::string& name) {
  if (name == "dynamics") return TaskFidelity::kDynamics;
  if (name == "kinematic") return TaskFidelity::kKinematic;
  throw Error("parking task: fidelity: unknown value '" + name +
              "' (expected dynamics or kinematic)");
}

void validateTaskDef(const ParkingTaskDef& def) {
  const auto fail = [](const char* field, const std::string& rule, double value) {
    throw Error(std::string("parking task: ") + field + " must be " + rule + ", got " +
                formatGeneral(value));
  };
  const auto positive = [&fail](const char* field, double value) {
    if (!(value > 0.0 && std::isfinite(value))) fail(field, "positive and finite", value);
  };
  const auto notNegative = [&fail](const char* field, double value) {
    if (!(value >= 0.0 && std::isfinite(value))) fail(field, "finite and not negative", value);
  };
  const auto notPositive = [&fail](const char* field, double value) {
    if (!(value <= 0.0 && std::isfinite(value))) fail(field, "finite and not positive", value);
  };
  positive("control_period_s", def.control_period_s);
  if (def.max_episode_steps < 0 || def.max_episode_steps > kMaxTaskEpisodeSteps) {
    fail("max_episode_steps",
         "in [0, " + std::to_string(kMaxTaskEpisodeSteps) + "] (0: no limit of the task's own)",
         def.max_episode_steps);
  }
  notNegative("start_position_noise_m", def.start_position_noise_m);
  notNegative("start_heading_noise_rad", def.start_heading_noise_rad);
  notNegative("success_position_m", def.success_position_m);
  notNegative("success_heading_rad", def.success_heading_rad);
  positive("distance_scale_m", def.distance_scale_m);
  notNegative("heading_weight", def.heading_weight);
  // The signs keep every successful park above every crash, exit and time-out.
  positive("success_reward", def.success_reward);
  notPositive("contact_reward", def.contact_reward);
  notPositive("exit_reward", def.exit_reward);
  if (!(def.discount > 0.0 && def.discount <= 1.0)) fail("discount", "in (0, 1]", def.discount);
  notNegative("shaping_weight", def.shaping_weight);
  positive("kinematic_check_m", def.kinematic_check_m);
  if (def.fidelity == TaskFidelity::kKinematic && def.realism.active()) {
    throw Error("parking task: the kinematic fidelity drives the ideal robot; realism '" +
                def.realism.name + "' needs fidelity dynamics");
  }
  validateRealism(def.realism);
}

}  // namespace parksim
