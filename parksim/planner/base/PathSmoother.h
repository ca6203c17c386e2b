#pragma once
// Smoothing for every planner's plan, on its exact geometry (pieces of constant wheel-speed
// direction, TimeOptimalTiming.h), scored by the duration of its time-optimal timing:
// 1. shortcuts: a stretch of the path between two of its poses is replaced by a free-space
//    connection between them when that is collision-free and makes the plan faster. The
//    candidates are the fastest path at full wheel speed (Balkcom-Mason, BalkcomMason.h: turns
//    in place and straight drives) and the shortest Reeds-Shepp curves of a few radii, whose arcs
//    need no stop where a turn in place does; they are timed with the rest of the plan and
//    checked fastest first. First deterministically, from each pose where pieces join to the
//    farthest such pose at halving distances, then between random poses anywhere along the
//    path (not only where pieces join), drawn from the caller's seeded generator;
// 2. fillets: a turn in place between two straight drives the same way becomes an arc tangent
//    to both (the largest radius of a list that is collision-free and faster): an arc turns the
//    robot without the stop a turn in place needs, and cuts the corner.
// Every new stretch is checked by the gap-free MotionValidator before it is kept, so the result
// is as valid as the input; it starts where the input starts and ends where it ends (up to
// rounding).
//
// A car's smoothing (the constructor with CarLimits) offers only Reeds-Shepp curves at a few
// multiples of its tightest radius (a car cannot turn in place, so it has no corners to fillet)
// and scores paths by the duration of the car's plan along them (CarPlanAlong.h), estimated per
// piece by CarTimeCost.h.

#include <memory>
#include <optional>
#include <random>
#include <vector>

#include "parksim/core/geometry/Pose2.h"
#include "parksim/core/model/RobotDef.h"
#include "parksim/planner/motion/CarTiming.h"
#include "parksim/planner/motion/MotionValidator.h"
#include "parksim/planner/motion/TimeOptimalTiming.h"
#include "parksim/planner/steering/ReedsSheppSteering.h"

namespace parksim {

struct PathSmootherDef {
  /// Radii of the Reeds-Shepp curves offered as shortcuts beside the Balkcom-Mason path, m
  /// (each > 0); empty: Balkcom-Mason only.
  std::vector<double> curve_radii_m{0.05, 0.1, 0.2, 0.4};
  /// Fillet radii tried at each corner, largest first, m (each > 0); empty: no fillets.
  std::vector<double> fillet_radii_m{0.4, 0.25, 0.16, 0.1, 0.06, 0.04, 0.025};
  /// A car's Reeds-Shepp shortcuts: curves at these multiples (each >= 1) of its minimum
  /// turning radius.
  std::vector<double> car_curve_radii{1.0, 1.5, 2.0, 3.0};
};

struct PathSmoothingStats {
  int shortcuts = 0;      ///< shortcuts kept
  int fillets = 0;        ///< corners turned into arcs
  int validated = 0;      ///< candidate stretches checked by the motion validator
  double before_s = 0.0;  ///< duration of the input as timed, s
  double after_s = 0.0;   ///< duration of the result as timed, s
};

class PathSmoother {
 public:
  /// `limits` time the candidates (the plan's own timing limits).
  PathSmoother(const RobotDef& robot, const MotionValidator& validator, const TimingLimits& limits,
               const PathSmootherDef& def = {});
  /// A car's smoothing (see the file comment): `limits` time the candidates as car plans.
  PathSmoother(const CarLimits& limits, const RobotDef& car, const MotionValidator& validator,
               const PathSmootherDef& def = {});
  ~PathSmoother();
  PathSmoother(const PathSmoother&) = delete;
  PathSmoother& operator=(const PathSmoother&) = delete;

  /// The free-space connections from `from` to `to` offered as shortcuts (see the file
  /// comment), each as pieces: the Balkcom-Mason path first, then a Reeds-Shepp curve per radius.
  std::vector<std::vector<PathPiece>> connections(const Pose2& from, const Pose2& to) const;

  /// The smoothed path from `start`, with `random_shortcuts` (>= 0) shortcuts between random
  /// poses after the bisection pass; never slower than `pieces` as timed.
  std::vector<PathPiece> smooth(const Pose2& start, std::vector<PathPiece> pieces,
                                int random_shortcuts, std::mt19937_64& rng,
                                PathSmoothingStats* stats = nullptr) const;

  /// The duration of `pieces` as timed (TimeOptimalTiming.h; a car's: CarPlanAlong.h), s.
  double duration(const std::vector<PathPiece>& pieces) const;
  /// The estimated time of `stretch` between pieces of directions `before` and `after`
  /// (PathPiece::direction; zero wheel speeds: rest), s (TimeCost.h; a car's: CarTimeCost.h).
  double stretchTime(const WheelSpeeds& before, const std::vector<PathPiece>& stretch,
                     const WheelSpeeds& after) const;

 private:
  RobotDef robot_;
  const MotionValidator& validator_;
  TimingLimits limits_;
  PathSmootherDef def_;
  std::vector<std::unique_ptr<ReedsSheppSteering>> curves_;
  std::optional<CarLimits> car_;  // set for a car
};

}  // namespace parksim
