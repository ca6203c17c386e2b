#include "parksim/sim/control/CarTracking.h"

#include <algorithm>
#include <cmath>

#include "parksim/sim/control/TrackingController.h"

namespace parksim {

CarTrackingGains carTrackingGains(const TrackingDef& def, const RobotDef& car,
                                  double plan_top_speed_mps, double period_s, double latency_s) {
  const TrackingGains along = trackingGains(def, car, plan_top_speed_mps, period_s, latency_s);
  double lambda = def.car_path_bandwidth_1pm;
  if (lambda <= 0.0) {
    lambda = 2.0 / car.axle_distance_m;
    const double v = std::max(plan_top_speed_mps, 0.05 * car.topSpeed());
    lambda = std::min(lambda, along.k_x / v);
  }
  return {along.k_x, lambda * lambda, 2.0 * def.car_damping * lambda};
}

CarCommand carTrackingCommand(const Pose2& actual, const Pose2& reference,
                              double reference_speed_mps, double reference_steer_rad,
                              const CarTrackingGains& gains, const RobotDef& car) {
  const TrackingError e = trackingError(actual, reference);
  const double v_r = reference_speed_mps;
  CarCommand out;
  const double v = v_r * std::cos(e.heading_rad) + gains.k_x * e.along_m;
  out.speed_mps = std::clamp(v, -car.max_speed_mps, car.max_speed_mps);
  const double direction = v_r > 0.0   ? 1.0
                           : v_r < 0.0 ? -1.0
                           : v > 0.0   ? 1.0
                           : v < 0.0   ? -1.0
                                       : 0.0;
  const double curvature = std::tan(reference_steer_rad) / car.axle_distance_m +
                           gains.k_y * e.cross_m +
                           gains.k_theta * direction * std::sin(e.heading_rad);
  out.steer_rad =
      std::clamp(std::atan(car.axle_distance_m * curvature), -car.max_steer_rad, car.max_steer_rad);
  return out;
}

}  // namespace parksim
