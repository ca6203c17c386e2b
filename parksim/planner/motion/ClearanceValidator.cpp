#include "parksim/planner/motion/ClearanceValidator.h"

#include <algorithm>
#include <cmath>

namespace parksim {

namespace {

// Poses this close (m and rad) are the spared pose itself, up to rounding.
constexpr double kSame = 1e-9;

// How far the lot may shrink on each side and still hold every spared pose with the validator's
// own margin (`half`): at most `extra`.
LotBounds shrunk(const LotBounds& lot, double extra, double half,
                 const std::vector<Pose2>& spared) {
  double left = extra, bottom = extra, right = extra, top = extra;
  for (const Pose2& p : spared) {
    left = std::min(left, std::max(0.0, p.x - lot.x_min_m - half));
    bottom = std::min(bottom, std::max(0.0, p.y - lot.y_min_m - half));
    right = std::min(right, std::max(0.0, lot.x_max_m - p.x - half));
    top = std::min(top, std::max(0.0, lot.y_max_m - p.y - half));
  }
  return {lot.x_min_m + left, lot.y_min_m + bottom, lot.x_max_m - right, lot.y_max_m - top};
}

// The extra margin: half the resolution, and a thousandth of that for rounding.
double extraFor(const MotionValidatorDef& def, const RobotDef& robot) {
  return 0.5005 * resolvedValidation(def, robot).resolution_m;
}

}  // namespace

bool ClearanceValidator::Grown::isFree(const Pose2& pose, double margin_m) const {
  for (const Pose2& s : spared_) {
    if (positionDistance(pose, s) <= kSame && headingDistance(pose, s) <= kSame) {
      return inner_.isFree(pose, margin_m);
    }
  }
  return inner_.isFree(pose, margin_m + extra_m_);
}

ClearanceValidator::ClearanceValidator(const FootprintChecker& checker, const RobotDef& robot,
                                       const LotBounds& lot, const MotionValidatorDef& def,
                                       std::vector<Pose2> spared)
    : grown_(checker, extraFor(def, robot), spared),
      validator_(grown_, robot,
                 shrunk(lot, extraFor(def, robot),
                        0.5 * resolvedValidation(def, robot).resolution_m, spared),
                 def) {}

}  // namespace parksim
