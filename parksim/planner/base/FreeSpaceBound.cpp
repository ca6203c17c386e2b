#include "parksim/planner/base/FreeSpaceBound.h"

#include <algorithm>
#include <cmath>

#include "parksim/core/geometry/Angle.h"
#include "parksim/core/io/Error.h"
#include "parksim/planner/steering/BalkcomMason.h"
#include "parksim/planner/steering/ReedsSheppSteering.h"

namespace parksim {

namespace {

// The fewest periods of `dt` in which speeds held a period each, changing by at most `step` a
// period from rest and to rest and never above `v`, cover `travel`, times dt.
double restToRestDuration(double travel, double v, double step, double dt) {
  if (!(travel > 0.0)) return 0.0;
  // Envelope of n periods: ramps of `ramp` periods at each end (speeds k step, capped at v),
  // full speed between. Its area grows with n; the fewest periods that cover `travel` count.
  auto envelope = [&](long n) {
    double area = 0.0;
    for (long k = 1; k <= n; ++k) area += std::min({v, k * step, (n + 1 - k) * step});
    return area * dt;
  };
  // Full speed all the way is never beaten: start there and step up.
  long n = std::max(1L, static_cast<long>(std::floor(travel / (v * dt))));
  while (envelope(n) < travel) {
    // Jump close to the answer when far below it (each period adds at most v dt).
    const long jump = static_cast<long>((travel - envelope(n)) / (v * dt));
    n += std::max(1L, jump);
  }
  return static_cast<double>(n) * dt;
}

}  // namespace

double freeSpaceDurationBound(const Pose2& from, const Pose2& to, const RobotDef& robot,
                              const TimingLimits& limits) {
  const double v = limits.max_wheel_speed_radps;
  const double dt = limits.period_s;
  const double step = limits.max_wheel_accel_radps2 * dt;
  if (!(v > 0.0) || !(step > 0.0) || !(dt > 0.0)) {
    throw Error("free-space bound: wheel speed, acceleration and period must be positive");
  }
  const double travel = balkcomMasonCost(from, to, 0.5 * robot.wheel_base_m) / robot.wheel_radius_m;
  return restToRestDuration(travel, v, step, dt);
}

double carFreeSpaceDurationBound(const Pose2& from, const Pose2& to, const RobotDef& car,
                                 double period_s) {
  if (!(car.max_speed_mps > 0.0) || !(car.max_accel_mps2 > 0.0) || !(period_s > 0.0)) {
    throw Error("free-space bound: the car's speed, acceleration and the period must be positive");
  }
  ReedsSheppDef def;
  def.turning_radius_m = car.minTurningRadius();
  def.period_s = period_s;
  const double length = ReedsSheppSteering(car, def).distance(from, to);
  return restToRestDuration(length, car.max_speed_mps, car.max_accel_mps2 * period_s, period_s);
}

double scenarioFreeSpaceBound(const Scenario& scenario, const TimingLimits& limits) {
  const auto bound = [&](const Pose2& to) {
    return scenario.robot.isCar()
               ? carFreeSpaceDurationBound(scenario.start, to, scenario.robot, limits.period_s)
               : freeSpaceDurationBound(scenario.start, to, scenario.robot, limits);
  };
  const Pose2& goal = scenario.goal.pose;
  double free_space = bound(goal);
  if (scenario.goal.either_heading) {
    free_space = std::min(free_space, bound({goal.x, goal.y, goal.theta + kPi}));
  }
  return free_space;
}

}  // namespace parksim
