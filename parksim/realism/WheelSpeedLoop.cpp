#include "parksim/realism/WheelSpeedLoop.h"

#include <algorithm>

namespace parksim {

WheelSpeedLoop::WheelSpeedLoop(const WheelSpeedLoopDef& def, double no_load_speed_radps,
                               double supply_limit)
    : def_(def), no_load_(no_load_speed_radps), limit_(supply_limit) {}

double WheelSpeedLoop::update(double setpoint_radps, double measured_radps, double period_s) {
  const double error = setpoint_radps - measured_radps;
  const double feed = setpoint_radps / no_load_ + def_.kp * error;
  // Conditional integration: the integrator only grows while the output is not saturated in
  // the same direction (no wind-up through a stall or a slip).
  const double next = integral_ + def_.ki * error * period_s;
  const double unclamped = feed + next;
  if (std::abs(unclamped) <= limit_ || unclamped * error < 0.0) integral_ = next;
  effort_ = std::clamp(feed + integral_, -limit_, limit_);
  return effort_;
}

}  // namespace parksim
