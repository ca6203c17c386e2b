#include "parksim/core/model/Ackermann.h"

#include <cmath>

namespace parksim {

FrontWheelAngles ackermannAngles(const RobotDef& car, double steer_rad) {
  const double l = car.axle_distance_m;
  const double half_track = 0.5 * car.wheel_base_m;
  const double k = l * std::tan(steer_rad);  // L tan(delta), m
  // atan2 with a positive denominator keeps each wheel's angle on the bicycle angle's side.
  return {std::atan2(k, l - half_track * std::tan(steer_rad)),
          std::atan2(k, l + half_track * std::tan(steer_rad))};
}

double bicycleAngle(const RobotDef& car, const FrontWheelAngles& wheels) {
  const double l = car.axle_distance_m;
  const double half_track = 0.5 * car.wheel_base_m;
  // Each wheel's relation solved for tan(delta): tan(delta) = L tan(w) / (L +- t/2 tan(w)).
  const double tl = std::tan(wheels.left_rad);
  const double tr = std::tan(wheels.right_rad);
  const double from_left = l * tl / (l + half_track * tl);
  const double from_right = l * tr / (l - half_track * tr);
  return std::atan(0.5 * (from_left + from_right));
}

double steerCurvature(const RobotDef& car, double steer_rad) {
  return std::tan(steer_rad) / car.axle_distance_m;
}

double curvatureSteer(const RobotDef& car, double curvature_1pm) {
  return std::atan(car.axle_distance_m * curvature_1pm);
}

WheelSpeeds carWheelSpeeds(const RobotDef& car, double speed_mps, double steer_rad) {
  return toWheelSpeeds({speed_mps, speed_mps * steerCurvature(car, steer_rad)}, car);
}

}  // namespace parksim
