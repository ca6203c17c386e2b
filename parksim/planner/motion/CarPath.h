#pragma once
// A car's path as geometry (docs/planning.md, "Cars"): sections driven one way, each with a
// curvature that is constant or changes linearly with the distance driven (a clothoid). The
// searches and the Reeds-Shepp curves give paths of constant-curvature pieces (PathPiece,
// TimeOptimalTiming.h) whose curvature jumps where they join; a car's steering cannot jump, so
// where two pieces driven the same way join, transitions() replaces the jump by a clothoid
// centred on it. A centred clothoid turns the car as much as the jump did, but moves the rest of
// the path sideways by about dk h^2 / 6 (dk the jump, 2h the clothoid's length), so
// correctedEnd() then stretches or shortens the constant-curvature sections until the path ends
// where it did again. Where a jump stays (a transition of length 0, or between sections driven
// opposite ways), the car stops and steers standing (CarTiming.h).

#include <functional>
#include <optional>
#include <vector>

#include "parksim/core/geometry/Pose2.h"
#include "parksim/core/model/RobotDef.h"
#include "parksim/planner/motion/TimeOptimalTiming.h"

namespace parksim {

struct CarSection {
  int direction = 1;         ///< +1 forward, -1 reverse
  double length_m = 0.0;     ///< distance the reference point drives, m (> 0)
  double kappa_begin = 0.0;  ///< curvature at its start, 1/m (yaw rate / speed: tan(steer) / axle)
  double kappa_end = 0.0;    ///< at its end; linear in between, 1/m
  /// Heading change over the section, rad.
  double turn() const { return direction * 0.5 * (kappa_begin + kappa_end) * length_m; }
  bool constantCurvature() const { return kappa_begin == kappa_end; }
};

/// The sections of a path of pieces driven by `car`: one constant-curvature section per piece
/// (pieces of one direction and curvature merged). Throws Error on a piece that turns in place
/// or is sharper than the car's maxCurvature() (beyond rounding).
std::vector<CarSection> carSections(const std::vector<PathPiece>& pieces, const RobotDef& car);

/// True when the car stops between sections `a` and `b` (driven one after the other): they are
/// driven opposite ways, or the curvature jumps between them.
bool stopsBetween(const CarSection& a, const CarSection& b);

/// Where driving `sections` from `start` leads (clothoids integrated in steps of at most
/// `step_m`, each an arc of its mean curvature).
Pose2 endOf(const Pose2& start, const std::vector<CarSection>& sections, double step_m = 0.02);

/// `sections` with every curvature jump between sections driven the same way replaced by a
/// clothoid centred on it, of half-length `half_length(junction, kappa before, kappa after)`
/// (m, >= 0; 0 leaves the jump; `junction` i joins sections i and i + 1), but at most half of
/// either neighbouring section's length. `junction_of`, when given, is set to each returned
/// section's junction for clothoids, and to -1 for the others.
std::vector<CarSection> transitions(
    const std::vector<CarSection>& sections,
    const std::function<double(std::size_t junction, double kappa_before, double kappa_after)>&
        half_length,
    std::vector<long>* junction_of = nullptr);

/// `sections` with the lengths of their constant-curvature sections changed, the longer ones
/// more, so that from `start` they end at `target` (to 1e-9 m and rad), by Newton's method on
/// the least weighted change; nothing when that does not converge or would shorten a section
/// below `min_length_m`.
std::optional<std::vector<CarSection>> correctedEnd(const Pose2& start,
                                                    std::vector<CarSection> sections,
                                                    const Pose2& target,
                                                    double min_length_m = 1e-3);

}  // namespace parksim
