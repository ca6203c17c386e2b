#pragma once
// Definition of the ego robot: a differential drive (the default, the study's robot) or a
// front-steered car (drive == Drive::kCar, docs/cars.md). Defaults are the study's robot; a
// car's are midSizeCar()'s.
//
// Both kinds share one reference point, the middle of the axle whose wheels do not steer (the
// differential drive's axle, a car's rear axle), and one plan representation: the two wheels on
// that axle, wheel_base_m apart (a car's track), with their angular speeds (Trajectory.h). A car
// adds a steering angle and the limits that make its plans drivable: curvature within
// tan(max_steer_rad) / axle_distance_m, steering rate, speed and acceleration.

#include <cmath>

namespace parksim {

/// How the robot drives.
enum class Drive {
  kDifferential,  ///< two independently driven wheels on one axle; turns in place
  kCar,           ///< front-steered (bicycle model), driven rear axle; cannot turn in place
};

/// The study robot's size: the longer side of its 80 x 85 mm footprint, m. What parksim tuned
/// for the study's robot and holds for a robot of any size (margins, motion-check steps, the
/// simulation's sliders, the film's camera) is the study's value times RobotDef::sizeScale().
inline constexpr double kStudyRobotSize_m = 0.085;
/// The study robot's top speed: 10 rad/s wheels of 20 mm radius, m/s.
inline constexpr double kStudyTopSpeed_mps = 10.0 * 0.020;

struct RobotDef {
  /// Footprint length along the heading, m.
  double length_m = 0.080;
  /// Footprint width across the heading, m.
  double width_m = 0.085;
  /// Distance from the reference point (axle middle) forward to the front edge, m.
  /// The body reaches length_m - front_overhang_m behind the reference point.
  double front_overhang_m = 0.010;
  /// How it drives: world files' `robot.drive` (differential | car).
  Drive drive = Drive::kDifferential;
  /// Distance between the two wheels' contact points, m. A car's `track`: between its rear
  /// wheels' contact points.
  double wheel_base_m = 0.085;
  /// Wheel radius, m.
  double wheel_radius_m = 0.020;
  /// Largest wheel angular speed magnitude, rad/s.
  double max_wheel_speed_radps = 10.0;
  /// Largest wheel angular acceleration magnitude, rad/s^2.
  double max_wheel_accel_radps2 = 40.0;
  /// Body height, used by physics and rendering, m.
  double height_m = 0.050;
  /// Height of the chassis' underside above the ground, m. Obstacles no higher than this pass
  /// under the robot (the planner ignores them; the simulated chassis clears them).
  double ground_clearance_m = 0.002;

  // A car's own limits (drive == Drive::kCar; a differential drive ignores them).
  /// Rear axle to front axle (the bicycle model's wheelbase), m.
  double axle_distance_m = 2.8;
  /// Largest front-wheel angle of the bicycle model, rad (world files: max_steer_deg).
  double max_steer_rad = 0.75;
  /// Largest rate of the steering angle, rad/s (world files: max_steer_rate_degps).
  double max_steer_rate_radps = 0.5;
  /// Largest speed of the reference point, forward or reverse, m/s.
  double max_speed_mps = 2.5;
  /// Largest acceleration of the reference point along the heading, m/s^2.
  double max_accel_mps2 = 1.0;

  bool isCar() const { return drive == Drive::kCar; }
  /// A car's largest curvature of the reference point's path, 1/m: tan(max_steer) / axle.
  double maxCurvature() const { return std::tan(max_steer_rad) / axle_distance_m; }
  /// A car's smallest turning radius of the reference point, m.
  double minTurningRadius() const { return axle_distance_m / std::tan(max_steer_rad); }

  /// Offset of the footprint's centre from the reference point along the heading, m
  /// (negative: the centre lies behind the axle).
  double footprintCenterOffset() const { return front_overhang_m - 0.5 * length_m; }

  /// The robot's size: the longer side of its footprint, m.
  double size() const { return length_m > width_m ? length_m : width_m; }
  /// Its size in study robots (size() / kStudyRobotSize_m): exactly 1 for the study's robot, so
  /// a study value times it is that value to the bit.
  double sizeScale() const { return size() / kStudyRobotSize_m; }
  /// Top speed of the reference point, m/s.
  double topSpeed() const {
    return isCar() ? max_speed_mps : max_wheel_speed_radps * wheel_radius_m;
  }
  /// The time it takes to drive its own size at top speed, in the study robot's (0.425 s):
  /// exactly 1 for the study's robot, 3.33 for a 4.25 m car at 3 m/s. Durations tuned for the
  /// study's robot (a steering horizon) are this many times longer for another.
  double timeScale() const { return sizeScale() / (topSpeed() / kStudyTopSpeed_mps); }
};

/// Sets a car's rear-wheel limits from its own (a world file gives a car no wheel limits):
/// the outer rear wheel's speed at the tightest turn and top speed, and its acceleration at the
/// car's (wheel speeds are what plans carry, Trajectory.h).
inline void setCarWheelLimits(RobotDef& car) {
  car.max_wheel_speed_radps =
      car.max_speed_mps * (1.0 + 0.5 * car.wheel_base_m * car.maxCurvature()) / car.wheel_radius_m;
  car.max_wheel_accel_radps2 = car.max_accel_mps2 / car.wheel_radius_m;
}

/// The car a world's `robot: {drive: car}` starts from before its other keys: a mid-size car
/// (4.689 x 1.942 m, 2.8 m between the axles, front wheels <= 0.75 rad at <= 0.5 rad/s,
/// 2.5 m/s, 1 m/s^2; the automated-parking benchmarks' car, docs/cars.md). The one place these
/// defaults are written.
inline RobotDef midSizeCar() {
  RobotDef car;
  car.drive = Drive::kCar;
  car.length_m = 4.689;
  car.width_m = 1.942;
  car.front_overhang_m = 3.739;  // 2.8 m wheelbase + 0.939 m front overhang past the front axle
  car.axle_distance_m = 2.8;
  car.wheel_base_m = 1.6;  // track
  car.wheel_radius_m = 0.33;
  car.max_steer_rad = 0.75;
  car.max_steer_rate_radps = 0.5;
  car.max_speed_mps = 2.5;
  car.max_accel_mps2 = 1.0;
  setCarWheelLimits(car);
  car.height_m = 1.5;
  car.ground_clearance_m = 0.15;
  return car;
}

}  // namespace parksim
