#include "parksim/planner/motion/CarTimeCost.h"

#include <algorithm>
#include <cmath>

#include "parksim/core/io/Error.h"

namespace parksim {

CarTimeCost::CarTimeCost(const RobotDef& car, const CarLimits& limits, double gear_change_penalty_s)
    : car_(car), limits_(limits), gear_change_penalty_s_(gear_change_penalty_s) {
  if (!(limits.max_speed_mps > 0.0) || !(limits.max_accel_mps2 > 0.0) ||
      !(limits.max_steer_rate_radps > 0.0) || !(gear_change_penalty_s >= 0.0)) {
    throw Error("car time cost: speed, acceleration and steering rate must be > 0, penalty >= 0");
  }
}

double CarTimeCost::pieceTime(double length_m, double kappa) const {
  const double wheels = limits_.max_wheel_speed_radps * car_.wheel_radius_m /
                        (1.0 + 0.5 * car_.wheel_base_m * std::abs(kappa));
  return length_m / std::min(limits_.max_speed_mps, wheels);
}

double CarTimeCost::junctionTime(int direction_a, double kappa_a, int direction_b, double kappa_b,
                                 double room_m) const {
  const double v_max = limits_.max_speed_mps;
  const double a = limits_.max_accel_mps2;
  const double rate = limits_.max_steer_rate_radps;
  auto steer = [&](double kappa) { return std::atan(car_.axle_distance_m * kappa); };
  if (direction_a == 0 || direction_b == 0) {
    // From rest (steering first from straight wheels) or to rest.
    const double standing = direction_a == 0 ? std::abs(steer(kappa_b)) / rate : 0.0;
    return 0.5 * v_max / a + standing;
  }
  if (direction_a != direction_b) {
    return v_max / a + std::abs(steer(kappa_b) - steer(kappa_a)) / rate + gear_change_penalty_s_;
  }
  if (kappa_a == kappa_b) return 0.0;
  const double h = std::max(0.0, room_m);
  // The speed that passes a clothoid of half-length h: its half-length at 1 m/s is per m/s.
  const double per_speed = clothoidHalfLength(kappa_a, kappa_b, 1.0, car_, limits_);
  const double v = std::min(v_max, h / per_speed);
  if (!(v > 1e-3 * v_max)) {
    // No room: it stops and steers standing.
    return v_max / a + std::abs(steer(kappa_b) - steer(kappa_a)) / rate;
  }
  return (v_max - v) * (v_max - v) / (a * v_max) + 2.0 * h * (1.0 / v - 1.0 / v_max);
}

}  // namespace parksim
