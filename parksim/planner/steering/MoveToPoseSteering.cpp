#include "parksim/planner/steering/MoveToPoseSteering.h"

#include <algorithm>
#include <cmath>

#include "parksim/core/io/Error.h"

namespace parksim {

namespace {

// Scales both wheels by one factor so the faster one meets the limit: the commanded curvature
// is kept and only the speed along the path drops.
WheelSpeeds limitSpeed(WheelSpeeds w, double max_speed) {
  const double fastest = std::max(std::abs(w.left_radps), std::abs(w.right_radps));
  if (fastest > max_speed) {
    const double s = max_speed / fastest;
    w.left_radps *= s;
    w.right_radps *= s;
  }
  return w;
}

WheelSpeeds limitAcceleration(const WheelSpeeds& w, const WheelSpeeds& prev, double max_step) {
  return {std::clamp(w.left_radps, prev.left_radps - max_step, prev.left_radps + max_step),
          std::clamp(w.right_radps, prev.right_radps - max_step, prev.right_radps + max_step)};
}

}  // namespace

MoveToPoseSteering::MoveToPoseSteering(const RobotDef& robot, const MoveToPoseDef& def)
    : robot_(robot), def_(def), finisher_(robot, RotateTranslateRotateDef{def.period_s}) {
  def_.horizon_s = steeringHorizon(def.horizon_s, robot);
  if (!(def.period_s > 0.0) || !(def_.horizon_s > 0.0) || !(def.max_duration_s > 0.0)) {
    throw Error("steering: period, horizon and max duration must be positive");
  }
  if (!(def.k_rho > 0.0) || !(def.k_alpha - def.k_rho > 0.0) || !(def.k_beta < 0.0)) {
    throw Error("steering: gains must satisfy k_rho > 0, k_alpha > k_rho, k_beta < 0 (stability)");
  }
  if (!(def.turn_in_place_radius_m > 0.0) ||
      def.turn_in_place_radius_m > def.position_tolerance_m) {
    throw Error("steering: turn_in_place_radius_m must be in (0, position_tolerance_m]");
  }
}

SteerResult MoveToPoseSteering::steer(const Pose2& from, const WheelSpeeds& from_wheels,
                                      const Pose2& to, SteerMode mode) const {
  const double dt = def_.period_s;
  const double duration = mode == SteerMode::kFixedHorizon ? def_.horizon_s : def_.max_duration_s;
  const int max_steps = static_cast<int>(std::lround(duration / dt));
  const double max_accel_step = robot_.max_wheel_accel_radps2 * dt;

  // Decide once whether to drive forwards or backwards. Flipping the direction whenever the
  // bearing crosses +-90 degrees makes the controller chatter; with the direction fixed, the
  // bearing stays in the half-plane it started in (Astolfi's stability argument).
  const double bearing0 = angleDiff(std::atan2(to.y - from.y, to.x - from.x), from.theta);
  const double direction = def_.allow_reverse && std::abs(bearing0) > 0.5 * kPi ? -1.0 : 1.0;

  SteerResult result;
  Trajectory& traj = result.trajectory;
  traj.points.reserve(static_cast<std::size_t>(max_steps) + 1);
  Pose2 pose = from;
  WheelSpeeds prev = from_wheels;
  auto arrived = [&](const Pose2& p) {
    return positionDistance(p, to) <= def_.position_tolerance_m &&
           headingDistance(p, to) <= def_.heading_tolerance_rad;
  };
  // A plan may end only where the robot can stop within one acceleration step.
  auto stoppable = [&](const WheelSpeeds& w) {
    return std::max(std::abs(w.left_radps), std::abs(w.right_radps)) <= max_accel_step;
  };
  // kExact hands over to the exact finisher once the position is nearly reached, where this
  // controller would only turn in place anyway.
  auto done = [&] {
    switch (mode) {
      case SteerMode::kFixedHorizon: return arrived(pose);
      case SteerMode::kToGoal: return arrived(pose) && stoppable(prev);
      case SteerMode::kExact: return positionDistance(pose, to) <= def_.turn_in_place_radius_m;
    }
    return false;
  };
  int step = 0;
  for (; step < max_steps && !done(); ++step) {
    const double dx = to.x - pose.x;
    const double dy = to.y - pose.y;
    const double rho = std::hypot(dx, dy);
    Twist cmd;
    if (rho > def_.turn_in_place_radius_m) {
      // Bearing of the target seen from the robot's direction of travel.
      double alpha = angleDiff(std::atan2(dy, dx), pose.theta);
      if (direction < 0.0) alpha = wrapAngle(alpha + kPi);
      const double beta = wrapAngle(to.theta - pose.theta - alpha);
      cmd.v_mps = direction * def_.k_rho * rho;
      cmd.omega_radps = def_.k_alpha * alpha + def_.k_beta * beta;
    } else {
      // Position reached: the beta mode (time constant ~12 s with the study's gains) would take
      // a minute to settle the heading, so turn in place instead.
      cmd.omega_radps = def_.k_alpha * angleDiff(to.theta, pose.theta);
    }
    const WheelSpeeds wheels = limitAcceleration(
        limitSpeed(toWheelSpeeds(cmd, robot_), robot_.max_wheel_speed_radps), prev, max_accel_step);
    traj.points.push_back({step * dt, pose, wheels});
    pose = integrateExact(pose, toTwist(wheels, robot_), dt);
    prev = wheels;
  }
  if (mode == SteerMode::kExact) {
    result.reached = done();
    if (!result.reached) {
      traj.points.push_back({step * dt, pose, {}});
      return result;
    }
    // Close the last fraction of a millimetre and the heading exactly: rotate-translate-rotate
    // from here, starting from the wheel speeds the controller leaves off with.
    const SteerResult finish = finisher_.steer(pose, prev, to, SteerMode::kExact);
    for (TrajectoryPoint p : finish.trajectory.points) {
      p.t_s += step * dt;
      traj.points.push_back(p);
    }
    return result;
  }
  traj.points.push_back({step * dt, pose, {}});
  result.reached = mode == SteerMode::kToGoal ? done() : arrived(pose);
  return result;
}

}  // namespace parksim
