#include "parksim/planner/ReedsSheppSteering.h"

#include <algorithm>
#include <cmath>

#include <ompl/base/spaces/ReedsSheppStateSpace.h>

#include "parksim/core/Error.h"

namespace parksim {

namespace ob = ompl::base;

struct ReedsSheppSteering::Curve {
  explicit Curve(double radius) : space(radius) {}
  ob::ReedsSheppStateSpace space;

  ob::ReedsSheppStateSpace::ReedsSheppPath path(const Pose2& from, const Pose2& to) const {
    // allocState per call keeps steer() const and safe to call from several threads.
    ob::State* a = space.allocState();
    ob::State* b = space.allocState();
    a->as<ob::SE2StateSpace::StateType>()->setXY(from.x, from.y);
    a->as<ob::SE2StateSpace::StateType>()->setYaw(from.theta);
    b->as<ob::SE2StateSpace::StateType>()->setXY(to.x, to.y);
    b->as<ob::SE2StateSpace::StateType>()->setYaw(to.theta);
    const ob::ReedsSheppStateSpace::ReedsSheppPath p = space.reedsShepp(a, b);
    space.freeState(a);
    space.freeState(b);
    return p;
  }
};

ReedsSheppSteering::ReedsSheppSteering(const RobotDef& robot, const ReedsSheppDef& def)
    : robot_(robot), def_(def) {
  if (!(def.turning_radius_m > 0.0)) throw Error("reeds-shepp steering: radius must be positive");
  if (!(def.period_s > 0.0) || !(def.horizon_s > 0.0)) {
    throw Error("reeds-shepp steering: period and horizon must be positive");
  }
  if (!(def.speed_fraction > 0.0 && def.speed_fraction <= 1.0)) {
    throw Error("reeds-shepp steering: speed fraction must be in (0, 1]");
  }
  if (!(robot.max_wheel_speed_radps > 0.0) || !(robot.max_wheel_accel_radps2 > 0.0)) {
    throw Error("reeds-shepp steering: wheel speed and accel limits must be positive");
  }
  curve_ = std::make_unique<Curve>(def.turning_radius_m);
}

ReedsSheppSteering::~ReedsSheppSteering() = default;

std::vector<PathPiece> ReedsSheppSteering::pieces(const Pose2& from, const Pose2& to) const {
  const auto path = curve_->path(from, to);
  const double rho = def_.turning_radius_m;
  std::vector<PathPiece> out;
  for (int i = 0; i < 5; ++i) {
    const double d = path.length_[i] * rho;  // signed: negative drives backwards, m
    if (path.type_[i] == ob::ReedsSheppStateSpace::RS_NOP || !(std::abs(d) > 1e-12)) continue;
    double kappa = 0.0;
    if (path.type_[i] == ob::ReedsSheppStateSpace::RS_LEFT) kappa = 1.0 / rho;
    if (path.type_[i] == ob::ReedsSheppStateSpace::RS_RIGHT) kappa = -1.0 / rho;
    // Moving d metres at curvature kappa turns the heading by d * kappa, in 1 s here.
    out.push_back(pieceOf(toWheelSpeeds({d, d * kappa}, robot_), 1.0));
  }
  return out;
}

double ReedsSheppSteering::distance(const Pose2& from, const Pose2& to) const {
  return curve_->path(from, to).length() * def_.turning_radius_m;
}

SteerResult ReedsSheppSteering::steer(const Pose2& from, const WheelSpeeds& from_wheels,
                                      const Pose2& to, SteerMode mode) const {
  const double dt = def_.period_s;
  const TimingLimits limits{def_.speed_fraction * robot_.max_wheel_speed_radps,
                            robot_.max_wheel_accel_radps2, dt};
  SteerResult result;
  // The path starts from rest.
  result.trajectory = brakeThenTimePieces(
      from, from_wheels, robot_, limits, [&](const Pose2& at_rest) { return pieces(at_rest, to); });
  finishAtTarget(result, to, mode, def_.horizon_s, dt);
  return result;
}

}  // namespace parksim
