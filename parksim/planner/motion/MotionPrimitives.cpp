#include "parksim/planner/motion/MotionPrimitives.h"

#include "parksim/core/io/Error.h"
#include "parksim/core/model/DiffDrive.h"

namespace parksim {

std::vector<MotionPrimitive> makePrimitives(double step_m, const std::vector<double>& radii_m,
                                            double turn_in_place_rad) {
  if (!(turn_in_place_rad >= 0.0)) {
    throw Error("motion primitives: step must be positive, in-place turn >= 0");
  }
  return makePrimitives(
      step_m, radii_m,
      turn_in_place_rad > 0.0 ? std::vector<double>{turn_in_place_rad} : std::vector<double>{});
}

std::vector<MotionPrimitive> makePrimitives(double step_m, const std::vector<double>& radii_m,
                                            const std::vector<double>& spin_angles_rad) {
  if (!(step_m > 0.0)) throw Error("motion primitives: step must be positive, in-place turn >= 0");
  std::vector<double> curvatures{0.0};
  for (double r : radii_m) {
    if (!(r > 0.0)) throw Error("motion primitives: radii must be positive");
    curvatures.push_back(1.0 / r);
    curvatures.push_back(-1.0 / r);
  }
  std::vector<MotionPrimitive> out;
  for (int dir : {1, -1}) {
    for (double kappa : curvatures) {
      const double d = dir * step_m;
      out.push_back({{d, d * kappa}, dir, step_m, std::abs(step_m * kappa)});
    }
  }
  for (double angle : spin_angles_rad) {
    if (!(angle > 0.0)) throw Error("motion primitives: in-place turns must be positive");
    for (double sign : {1.0, -1.0}) {
      out.push_back({{0.0, sign * angle}, 0, 0.0, angle});
    }
  }
  return out;
}

Pose2 applyPrimitive(const Pose2& from, const MotionPrimitive& m) {
  return integrateExact(from, m.motion, 1.0);
}

PathPiece pieceOf(const MotionPrimitive& m, const RobotDef& robot) {
  return pieceOf(toWheelSpeeds(m.motion, robot), 1.0);
}

Trajectory geometryOf(const Pose2& start, const std::vector<PathPiece>& pieces,
                      const RobotDef& robot) {
  Trajectory t;
  Pose2 pose = start;
  for (const PathPiece& p : pieces) {
    const WheelSpeeds w{p.direction.left_radps * p.travel_rad,
                        p.direction.right_radps * p.travel_rad};
    t.points.push_back({static_cast<double>(t.points.size()), pose, w});
    pose = integrateExact(pose, toTwist(w, robot), 1.0);
  }
  t.points.push_back({static_cast<double>(t.points.size()), pose, {}});
  return t;
}

}  // namespace parksim
