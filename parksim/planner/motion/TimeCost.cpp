#include "parksim/planner/motion/TimeCost.h"

#include <algorithm>
#include <cmath>

#include "parksim/core/io/Error.h"

namespace parksim {

TimeCostModel::TimeCostModel(const TimingLimits& limits)
    : limits_(limits),
      speed_(limits.max_wheel_speed_radps),
      step_(limits.max_wheel_accel_radps2 * limits.period_s) {
  if (!(speed_ > 0.0) || !(step_ > 0.0)) {
    throw Error("time cost: wheel speed, acceleration and period must be positive");
  }
}

double TimeCostModel::junctionTime(const WheelSpeeds& a, const WheelSpeeds& b) const {
  const double jump =
      std::max(std::abs(a.left_radps - b.left_radps), std::abs(a.right_radps - b.right_radps));
  if (!(jump > 0.0)) return 0.0;
  const double e = std::min(speed_, step_ / jump);
  const double both_sides = (speed_ - e) * (speed_ - e) / (limits_.max_wheel_accel_radps2 * speed_);
  // From or to rest there is one ramp, not two.
  const bool rest = a == WheelSpeeds{} || b == WheelSpeeds{};
  return rest ? 0.5 * both_sides : both_sides;
}

double TimeCostModel::duration(const std::vector<PathPiece>& pieces) const {
  double t = 0.0;
  WheelSpeeds last;  // rest
  for (const PathPiece& p : pieces) {
    t += pieceTime(p) + junctionTime(last, p.direction);
    last = p.direction;
  }
  return t + junctionTime(last, {});
}

}  // namespace parksim
