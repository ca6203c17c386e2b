#pragma once
// Timing a car's path (CarPath.h): rows one control period apart, each holding the rear wheels'
// speeds and the steering angle (Trajectory.h), within the car's limits.
//
// Between stops (CarPath.h's stopsBetween, and the start and the end) the car drives a run: it
// starts and ends at rest, its speed the fastest continuous-time profile at the acceleration
// limit below every cap along the run: the speed limit, the rear wheels' speed limit on each
// curvature, and on a clothoid the speed at which the steering turns at its rate limit
// (d steer / dt = v d steer / ds). A row holds the speed that covers, in its period, the distance
// that profile covers then, so the rows drive the run's length exactly, change speed by at most
// the acceleration limit times the period, and start and end at rest. A row's curvature is the
// mean of the path's over the distance it drives, so its heading change is the path's exactly
// (the clothoid's position is followed within micrometres). Where the car stops it steers
// standing, at the rate limit, to the next run's first angle: at the start from straight wheels.

#include <vector>

#include "parksim/core/geometry/Pose2.h"
#include "parksim/core/model/RobotDef.h"
#include "parksim/core/model/Trajectory.h"
#include "parksim/planner/motion/CarPath.h"

namespace parksim {

/// What a car's plan may use: the car's own limits, the steering rate less the feedback
/// headroom (a tracking controller corrects lateral and heading errors by steering).
struct CarLimits {
  double max_speed_mps = 2.5;          ///< of the reference point, m/s
  double max_accel_mps2 = 1.0;         ///< along the path, m/s^2
  double max_steer_rad = 0.75;         ///< front-wheel angle, rad
  double max_steer_rate_radps = 0.4;   ///< rad/s
  double max_wheel_speed_radps = 1e9;  ///< the rear wheels', rad/s
  double period_s = 0.02;              ///< rows this far apart, s
};

/// The limits of `car` leaving `headroom` (in [0, 1)) of its steering rate to a controller's
/// feedback, rows `period_s` apart.
CarLimits carLimits(const RobotDef& car, double headroom, double period_s);

/// The plan that drives `sections` from `start` (see the file comment): rows period_s apart from
/// t = 0, the last standing still. Throws Error when the limits are not positive or a section is
/// sharper than max_steer.
Trajectory timeCarPath(const Pose2& start, const std::vector<CarSection>& sections,
                       const RobotDef& car, const CarLimits& limits);

/// The duration timeCarPath's plan would have, s, without its rows.
double carPathDuration(const std::vector<CarSection>& sections, const RobotDef& car,
                       const CarLimits& limits);

/// The half-length of the clothoid from `kappa_a` to `kappa_b` that timeCarPath passes at
/// `speed_mps` with the steering at (its share of) the rate limit, m.
double clothoidHalfLength(double kappa_a, double kappa_b, double speed_mps, const RobotDef& car,
                          const CarLimits& limits);

/// The steering angle of curvature `kappa` for `car`, rad.
double steerOf(double kappa, const RobotDef& car);

}  // namespace parksim
