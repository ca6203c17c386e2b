#include "parksim/planner/base/FreeSpaceBound.h"

#include <algorithm>
#include <cmath>

#include "parksim/core/io/Error.h"
#include "parksim/planner/steering/BalkcomMason.h"

namespace parksim {

double freeSpaceDurationBound(const Pose2& from, const Pose2& to, const RobotDef& robot,
                              const TimingLimits& limits) {
  const double v = limits.max_wheel_speed_radps;
  const double dt = limits.period_s;
  const double step = limits.max_wheel_accel_radps2 * dt;
  if (!(v > 0.0) || !(step > 0.0) || !(dt > 0.0)) {
    throw Error("free-space bound: wheel speed, acceleration and period must be positive");
  }
  const double travel = balkcomMasonCost(from, to, 0.5 * robot.wheel_base_m) / robot.wheel_radius_m;
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

}  // namespace parksim
