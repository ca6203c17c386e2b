#include "parksim/planner/SpeedProfile.h"

#include <algorithm>
#include <cmath>

#include "parksim/core/Error.h"

namespace parksim {

namespace {

// Unscaled trapezoid speed of period i out of n: half a step at either end, ramps of one step
// per period, capped at max_speed.
double trapezoid(int i, int n, double max_speed, double max_step) {
  return std::min({(i + 0.5) * max_step, (n - i - 0.5) * max_step, max_speed});
}

}  // namespace

std::vector<double> restToRestProfile(double distance, double max_speed, double max_step,
                                      double period_s) {
  if (!(max_speed > 0.0) || !(max_step > 0.0) || !(period_s > 0.0) || !std::isfinite(distance)) {
    throw Error("speed profile: limits and period must be positive, distance finite");
  }
  const double target = std::abs(distance);
  if (target == 0.0) return {};
  // Area of the n-period trapezoid grows with n; find the first n that covers the distance. The
  // plateau adds max_speed * period_s per extra period, so jump close to the answer first.
  const double ramp = max_speed / max_step;  // periods to reach full speed
  int n = std::max(1, static_cast<int>(std::floor(target / (max_speed * period_s) - 2.0 * ramp)));
  auto area = [&](int periods) {
    double sum = 0.0;
    for (int i = 0; i < periods; ++i) sum += trapezoid(i, periods, max_speed, max_step);
    return sum * period_s;
  };
  while (area(n) < target) ++n;
  const double scale = target / area(n);
  const double sign = distance < 0.0 ? -1.0 : 1.0;
  std::vector<double> speeds(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) speeds[i] = sign * scale * trapezoid(i, n, max_speed, max_step);
  return speeds;
}

}  // namespace parksim
