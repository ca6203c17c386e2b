#include "parksim/planner/CarPlanAlong.h"

#include <cmath>

#include "parksim/planner/CarPath.h"

namespace parksim {

namespace {

// The clothoids' lengths tried, as shares of those that pass each jump at the speed limit.
constexpr double kShares[] = {1.0, 0.5, 0.25, 0.12, 0.0};

std::vector<CarSection> withClothoids(const std::vector<CarSection>& sections, double share,
                                      const RobotDef& car, const CarLimits& limits) {
  return transitions(sections, [&](double a, double b) {
    return share * clothoidHalfLength(a, b, limits.max_speed_mps, car, limits);
  });
}

}  // namespace

std::optional<Trajectory> carPlanAlong(const Pose2& start, const std::vector<PathPiece>& pieces,
                                       const RobotDef& car, const CarLimits& limits,
                                       const MotionValidator& validator, double end_tolerance_m,
                                       double* clothoid_share) {
  const std::vector<CarSection> sections = carSections(pieces, car);
  const Pose2 end = endOf(start, sections);
  for (double share : kShares) {
    std::vector<CarSection> path = sections;
    if (share > 0.0) {
      std::optional<std::vector<CarSection>> corrected =
          correctedEnd(start, withClothoids(sections, share, car, limits), end);
      if (!corrected) continue;
      path = std::move(*corrected);
    }
    Trajectory plan = timeCarPath(start, path, car, limits);
    const Pose2& reached = plan.points.back().pose;
    if (positionDistance(reached, end) > end_tolerance_m ||
        headingDistance(reached, end) * car.axle_distance_m > end_tolerance_m) {
      continue;
    }
    if (!validator.isValid(plan)) continue;
    if (clothoid_share) *clothoid_share = share;
    return plan;
  }
  return std::nullopt;
}

double carPlanDuration(const std::vector<PathPiece>& pieces, const RobotDef& car,
                       const CarLimits& limits) {
  return carPathDuration(withClothoids(carSections(pieces, car), 1.0, car, limits), car, limits);
}

}  // namespace parksim
