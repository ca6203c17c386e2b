// A car driven by wheel speeds (Controller.h's carCommandOfWheels).

#include <algorithm>
#include <cmath>

#include "parksim/sim/control/Controller.h"

namespace parksim {

CarCommand carCommandOfWheels(const WheelSpeeds& wheels, const RobotDef& car,
                              double measured_steer_rad) {
  const Twist twist = toTwist(wheels, car);
  CarCommand out;
  out.speed_mps = std::clamp(twist.v_mps, -car.max_speed_mps, car.max_speed_mps);
  const double steer = std::abs(twist.v_mps) > 1e-3
                           ? std::atan(car.axle_distance_m * twist.omega_radps / twist.v_mps)
                           : measured_steer_rad;
  out.steer_rad = std::clamp(steer, -car.max_steer_rad, car.max_steer_rad);
  return out;
}

}  // namespace parksim
