#include "parksim/planner/steering/RotateTranslateRotateSteering.h"

#include <algorithm>
#include <cmath>

#include "parksim/core/io/Error.h"
#include "parksim/planner/motion/SpeedProfile.h"

namespace parksim {

namespace {

// Positions closer than this are treated as equal: no translation phase, m.
constexpr double kSamePositionM = 1e-12;

}  // namespace

RotateTranslateRotateSteering::RotateTranslateRotateSteering(const RobotDef& robot,
                                                             const RotateTranslateRotateDef& def)
    : robot_(robot), def_(def) {
  def_.horizon_s = steeringHorizon(def.horizon_s, robot);
  if (!(def.period_s > 0.0) || !(def_.horizon_s > 0.0)) {
    throw Error("rotate-translate-rotate steering: period and horizon must be positive");
  }
  if (!(def.speed_fraction > 0.0 && def.speed_fraction <= 1.0) ||
      !(def.accel_fraction > 0.0 && def.accel_fraction <= 1.0)) {
    throw Error("rotate-translate-rotate steering: speed and accel fractions must be in (0, 1]");
  }
  if (!(robot.max_wheel_speed_radps > 0.0) || !(robot.max_wheel_accel_radps2 > 0.0)) {
    throw Error("rotate-translate-rotate steering: wheel speed and accel limits must be positive");
  }
}

SteerResult RotateTranslateRotateSteering::steer(const Pose2& from, const WheelSpeeds& from_wheels,
                                                 const Pose2& to, SteerMode mode) const {
  const double dt = def_.period_s;
  const double wheel_max = def_.speed_fraction * robot_.max_wheel_speed_radps;
  const double wheel_step = def_.accel_fraction * robot_.max_wheel_accel_radps2 * dt;
  const double r = robot_.wheel_radius_m;
  const double half_base = 0.5 * robot_.wheel_base_m;

  SteerResult result;
  Trajectory& traj = result.trajectory;
  Pose2 pose = from;
  // Holds `wheels` for one period: records the point and integrates exactly what it records.
  auto emit = [&](const WheelSpeeds& wheels) {
    traj.points.push_back({static_cast<double>(traj.points.size()) * dt, pose, wheels});
    pose = integrateExact(pose, toTwist(wheels, robot_), dt);
  };

  // Brake until both wheels are within half a step of rest, so the first phase's half step
  // follows within one acceleration step.
  WheelSpeeds w = from_wheels;
  while (std::max(std::abs(w.left_radps), std::abs(w.right_radps)) > 0.5 * wheel_step) {
    w.left_radps -= std::clamp(w.left_radps, -wheel_step, wheel_step);
    w.right_radps -= std::clamp(w.right_radps, -wheel_step, wheel_step);
    emit(w);
  }

  // In-place turn: the wheels run at -/+ omega * half_base / r.
  auto rotate = [&](double angle) {
    for (double omega :
         restToRestProfile(angle, wheel_max * r / half_base, wheel_step * r / half_base, dt)) {
      emit(toWheelSpeeds({0.0, omega}, robot_));
    }
  };
  auto translate = [&](double distance) {
    for (double v : restToRestProfile(distance, wheel_max * r, wheel_step * r, dt)) {
      emit(toWheelSpeeds({v, 0.0}, robot_));
    }
  };

  const double dx = to.x - pose.x;
  const double dy = to.y - pose.y;
  const double dist = std::hypot(dx, dy);
  if (dist > kSamePositionM) {
    const double bearing = std::atan2(dy, dx);
    // Face the target and drive forward, or face away and reverse: the one that turns less.
    const double fwd1 = angleDiff(bearing, pose.theta);
    const double fwd2 = angleDiff(to.theta, bearing);
    const double rev1 = angleDiff(bearing + kPi, pose.theta);
    const double rev2 = angleDiff(to.theta, bearing + kPi);
    const bool forward = std::abs(fwd1) + std::abs(fwd2) <= std::abs(rev1) + std::abs(rev2);
    rotate(forward ? fwd1 : rev1);
    // Drive along the heading actually reached (it differs from the bearing only by rounding);
    // the distance is measured afresh so the straight line ends on the target position.
    const double along = std::hypot(to.x - pose.x, to.y - pose.y);
    translate(forward ? along : -along);
  }
  rotate(angleDiff(to.theta, pose.theta));
  traj.points.push_back({static_cast<double>(traj.points.size()) * dt, pose, {}});

  finishAtTarget(result, to, mode, def_.horizon_s, dt);
  return result;
}

}  // namespace parksim
