#pragma once
// Planar pose of the robot's reference point (the middle of the wheel axle).

#include <cmath>

#include "parksim/core/geometry/Angle.h"

namespace parksim {

struct Pose2 {
  double x = 0.0;      ///< m, lot frame
  double y = 0.0;      ///< m, lot frame
  double theta = 0.0;  ///< rad, heading, counter-clockwise from +x

  friend bool operator==(const Pose2&, const Pose2&) = default;
};

/// Euclidean distance between the positions of two poses, m.
inline double positionDistance(const Pose2& a, const Pose2& b) {
  return std::hypot(a.x - b.x, a.y - b.y);
}

/// Absolute heading difference, rad, in [0, pi].
inline double headingDistance(const Pose2& a, const Pose2& b) {
  return std::abs(angleDiff(a.theta, b.theta));
}

}  // namespace parksim
