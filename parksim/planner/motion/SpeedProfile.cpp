#include "parksim/planner/motion/SpeedProfile.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "parksim/core/io/Error.h"
#include "parksim/core/io/NumberFormat.h"

namespace parksim {

namespace {

// Unscaled trapezoid speed of period i out of n: half a step at either end, ramps of one step
// per period, capped at max_speed.
double trapezoid(int i, int n, double max_speed, double max_step) {
  return std::min({(i + 0.5) * max_step, (n - i - 0.5) * max_step, max_speed});
}

}  // namespace

double restToRestPeriods(double distance, double max_speed, double max_step, double period_s) {
  // In units of max_step and periods: a triangle of n periods covers ~n^2/4, a trapezoid with
  // ramps of `ramp` periods covers ~(n - ramp) * ramp.
  const double area = std::abs(distance) / (period_s * max_step);
  const double ramp = max_speed / max_step;
  return area >= ramp * ramp ? area / ramp + ramp : 2.0 * std::sqrt(area);
}

std::vector<double> restToRestProfile(double distance, double max_speed, double max_step,
                                      double period_s) {
  if (!(max_speed > 0.0) || !(max_step > 0.0) || !(period_s > 0.0) || !std::isfinite(distance)) {
    throw Error("speed profile: limits and period must be positive, distance finite");
  }
  const double target = std::abs(distance);
  if (target == 0.0) return {};
  const double estimate = restToRestPeriods(distance, max_speed, max_step, period_s);
  if (!(estimate <= kMaxProfilePeriods)) {
    throw Error("speed profile: " + formatGeneral(estimate, 3) +
                " periods needed, more than the limit of " + formatGeneral(kMaxProfilePeriods) +
                " (docs/limits.md)");
  }
  // Area of the n-period trapezoid grows with n; find the first n that covers the distance,
  // starting from the estimate, which is within a few periods of it (O(n) work in all).
  auto area = [&](int periods) {
    double sum = 0.0;
    for (int i = 0; i < periods; ++i) sum += trapezoid(i, periods, max_speed, max_step);
    return sum * period_s;
  };
  int n = std::max(1, static_cast<int>(estimate) - 2);
  while (n > 1 && area(n - 1) >= target) --n;
  while (area(n) < target) ++n;
  const double scale = target / area(n);
  const double sign = distance < 0.0 ? -1.0 : 1.0;
  std::vector<double> speeds(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) speeds[i] = sign * scale * trapezoid(i, n, max_speed, max_step);
  return speeds;
}

}  // namespace parksim
