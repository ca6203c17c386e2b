#pragma once
// Test support: a short trajectory of arcs with varied wheel speeds, exactly integrated, that
// ends at rest (the core's and the result files' tests share it).

#include "parksim/core/geometry/Angle.h"
#include "parksim/core/model/DiffDrive.h"
#include "parksim/core/model/Trajectory.h"

namespace parksim::testing {

inline Trajectory sampleTrajectory() {
  const RobotDef robot;
  Trajectory t;
  Pose2 p{0.1, 0.1, kPi / 2};
  for (int i = 0; i < 10; ++i) {
    const WheelSpeeds w{3.0 + 0.1 * i, 4.0 - 0.2 * i};
    t.points.push_back({0.1 * i, p, w});
    p = integrateExact(p, toTwist(w, robot), 0.1);
  }
  t.points.push_back({1.0, p, {}});
  return t;
}

}  // namespace parksim::testing
