#include "parksim/planner/motion/CarPlanAlong.h"

#include <algorithm>
#include <cmath>

#include "parksim/planner/motion/CarPath.h"

namespace parksim {

namespace {

// A clothoid whose share falls below this is dropped (the car stops at its jump instead).
constexpr double kLeastShare = 0.1;
// Attempts per junction before every clothoid is dropped.
constexpr int kAttemptsPerJunction = 4;

std::vector<CarSection> withClothoids(const std::vector<CarSection>& sections,
                                      const std::vector<double>& share, const RobotDef& car,
                                      const CarLimits& limits,
                                      std::vector<long>* junction_of = nullptr) {
  return transitions(
      sections,
      [&](std::size_t j, double a, double b) {
        return share[j] * clothoidHalfLength(a, b, limits.max_speed_mps, car, limits);
      },
      junction_of);
}

// The distance `plan` drives until time t, m.
double distanceUntil(const Trajectory& plan, const RobotDef& car, double t) {
  double s = 0.0;
  for (std::size_t i = 0; i + 1 < plan.points.size(); ++i) {
    const TrajectoryPoint& p = plan.points[i];
    const double dt = std::min(plan.points[i + 1].t_s, t) - p.t_s;
    if (dt <= 0.0) break;
    s += std::abs(0.5 * car.wheel_radius_m * (p.wheels.left_radps + p.wheels.right_radps)) * dt;
  }
  return s;
}

void halve(double& share) { share = share * 0.5 < kLeastShare ? 0.0 : share * 0.5; }

}  // namespace

std::optional<Trajectory> carPlanAlong(const Pose2& start, const std::vector<PathPiece>& pieces,
                                       const RobotDef& car, const CarLimits& limits,
                                       const MotionValidator& validator, double end_tolerance_m,
                                       double* clothoid_share) {
  const std::vector<CarSection> sections = carSections(pieces, car);
  const Pose2 end = endOf(start, sections);
  std::vector<double> share(sections.size(), 1.0);
  const int attempts = kAttemptsPerJunction * static_cast<int>(sections.size()) + 4;
  auto report = [&](Trajectory plan) {
    if (clothoid_share) {
      double sum = 0.0;
      for (std::size_t j = 0; j + 1 < share.size(); ++j) sum += share[j];
      *clothoid_share = share.size() > 1 ? sum / static_cast<double>(share.size() - 1) : 1.0;
    }
    return std::optional<Trajectory>(std::move(plan));
  };
  for (int attempt = 0; attempt < attempts; ++attempt) {
    const bool any = std::any_of(share.begin(), share.end(), [](double x) { return x > 0.0; });
    if (!any) break;
    std::vector<long> junction_of;
    std::optional<std::vector<CarSection>> path =
        correctedEnd(start, withClothoids(sections, share, car, limits, &junction_of), end);
    if (!path) {
      for (double& x : share) halve(x);
      continue;
    }
    Trajectory plan = timeCarPath(start, *path, car, limits);
    const Pose2& reached = plan.points.back().pose;
    if (positionDistance(reached, end) > end_tolerance_m ||
        headingDistance(reached, end) * car.axle_distance_m > end_tolerance_m) {
      for (double& x : share) halve(x);
      continue;
    }
    const std::optional<MotionValidator::Failure> failure = validator.firstFailure(plan);
    if (!failure) return report(std::move(plan));
    // The clothoid that starts last before where the plan fails is made shorter (its sideways
    // shift is likely what meets the obstacle); failing before any, all of them are.
    const double at = distanceUntil(plan, car, failure->t_s);
    double s = 0.0;
    long culprit = -1;
    for (std::size_t k = 0; k < path->size() && s <= at; ++k) {
      if (junction_of[k] >= 0 && share[static_cast<std::size_t>(junction_of[k])] > 0.0) {
        culprit = junction_of[k];
      }
      s += (*path)[k].length_m;
    }
    if (culprit >= 0) {
      halve(share[static_cast<std::size_t>(culprit)]);
    } else {
      for (double& x : share) halve(x);
    }
  }
  // No clothoids: the car stops at every jump, on the pieces' own geometry.
  std::fill(share.begin(), share.end(), 0.0);
  Trajectory plan = timeCarPath(start, sections, car, limits);
  if (!validator.isValid(plan)) return std::nullopt;
  return report(std::move(plan));
}

double carPlanDuration(const std::vector<PathPiece>& pieces, const RobotDef& car,
                       const CarLimits& limits) {
  const std::vector<CarSection> sections = carSections(pieces, car);
  return carPathDuration(
      withClothoids(sections, std::vector<double>(sections.size(), 1.0), car, limits), car, limits);
}

}  // namespace parksim
