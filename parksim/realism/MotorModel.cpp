#include "parksim/realism/MotorModel.h"

#include <algorithm>

namespace parksim {

MotorModel::MotorModel(const MotorDef& def, double gain) : def_(def), gain_(gain) {}

double MotorModel::torque(double effort, double omega_radps) const {
  const double u = std::clamp(effort, -def_.supply_limit, def_.supply_limit);
  return def_.stall_torque_nm * (gain_ * u - omega_radps / def_.no_load_speed_radps);
}

double MotorModel::axleInertia() const {
  return def_.time_constant_s * def_.stall_torque_nm / def_.no_load_speed_radps;
}

double MotorModel::frictionTorque() const { return def_.startup_effort * def_.stall_torque_nm; }

double drawMotorGain(const MotorDef& def, std::mt19937_64& rng) {
  if (def.gain_mismatch_pct == 0.0) return 1.0;
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  return 1.0 + 0.01 * def.gain_mismatch_pct * u(rng);
}

}  // namespace parksim
