#pragma once
// A car's steering geometry (RobotDef::isCar, docs/cars.md): the bicycle model's front-wheel
// angle against the two front wheels' own angles (Ackermann: both wheels' axles point at the
// centre of the turn on the rear axle's line), and the rear wheels' speeds for a speed and
// steering angle. The front track is the rear one (RobotDef::wheel_base_m).
//
// With axle distance L, track t and bicycle angle delta (left positive), the turn's centre lies
// R = L / tan(delta) to the left of the reference point (the rear axle's middle), and
//   tan(delta_left)  = L / (R - t/2) = L tan(delta) / (L - t/2 tan(delta))
//   tan(delta_right) = L / (R + t/2) = L tan(delta) / (L + t/2 tan(delta)).

#include "parksim/core/model/DiffDrive.h"
#include "parksim/core/model/RobotDef.h"

namespace parksim {

/// The front wheels' steering angles, rad (left positive, as the bicycle angle).
struct FrontWheelAngles {
  double left_rad = 0.0;
  double right_rad = 0.0;
};

/// The front wheels' angles of bicycle angle `steer_rad` (|steer| < pi / 2; an inner wheel
/// whose turn centre would lie beyond it, |R| <= t/2, turns past 90 degrees as atan2 gives).
FrontWheelAngles ackermannAngles(const RobotDef& car, double steer_rad);

/// The bicycle angle of two front-wheel angles: the mean of the angles each wheel's own
/// Ackermann relation gives (exactly `steer` for ackermannAngles(car, steer)).
double bicycleAngle(const RobotDef& car, const FrontWheelAngles& wheels);

/// Curvature of the reference point's path at bicycle angle `steer_rad`, 1/m.
double steerCurvature(const RobotDef& car, double steer_rad);

/// The bicycle angle of path curvature `curvature_1pm`, rad.
double curvatureSteer(const RobotDef& car, double curvature_1pm);

/// The rear wheels' angular speeds that drive the reference point at `speed_mps` (negative:
/// reverse) on the curvature of `steer_rad`, without slip: what an ideal differential between
/// them turns them at.
WheelSpeeds carWheelSpeeds(const RobotDef& car, double speed_mps, double steer_rad);

}  // namespace parksim
