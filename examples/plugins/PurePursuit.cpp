// `pure-pursuit`: a controller as a user would write one against the plugin API. It steers for
// a point on the plan `lookahead_s` ahead of the reference (pure pursuit, Coulter 1992: the arc
// through the robot and that point has curvature 2 y / d^2 in the robot's frame), drives at the
// plan's speed corrected by the along-track error, and turns toward the plan's heading where
// the plan turns in place. Wheel speeds are scaled into the robot's limit.

#include <algorithm>
#include <cmath>

#include "ExamplePlugins.h"
#include "parksim/sim/control/TrackingController.h"

namespace example {

namespace {

struct PurePursuitDef {
  double lookahead_s = 0.4;       ///< how far ahead on the plan the pursued point is, s
  double min_lookahead_m = 0.02;  ///< the pursued point is at least this far, m
  double speed_gain = 4.0;        ///< 1/s: forward speed per metre of along-track error
  double heading_gain = 8.0;      ///< 1/s: yaw rate per radian of heading error (turns in place)
};

class PurePursuit : public parksim::Controller {
 public:
  explicit PurePursuit(const PurePursuitDef& def) : def_(def) {}

  void reset(const parksim::ControllerSetup& setup) override {
    robot_ = setup.scenario.robot;
    plan_ = setup.plan;
  }

  parksim::WheelSpeeds command(const parksim::ControllerInput& in) override {
    using namespace parksim;
    const Pose2& pose = in.pose;
    const double c = std::cos(pose.theta);
    const double s = std::sin(pose.theta);
    // The reference in the robot's frame.
    const double rx = c * (in.reference.x - pose.x) + s * (in.reference.y - pose.y);
    const double heading_err = std::remainder(in.reference.theta - pose.theta, 2.0 * M_PI);
    const double v_ref = in.reference_twist.v_mps;
    Twist cmd{v_ref + def_.speed_gain * rx, in.reference_twist.omega_radps};
    if (std::abs(v_ref) < 1e-4) {
      // Turning in place or standing: hold the position, follow the heading.
      cmd.omega_radps += def_.heading_gain * heading_err;
    } else {
      const Pose2 target = pointAhead(in.t_s, std::abs(v_ref));
      const double tx = c * (target.x - pose.x) + s * (target.y - pose.y);
      const double ty = -s * (target.x - pose.x) + c * (target.y - pose.y);
      const double d2 = tx * tx + ty * ty;
      if (d2 > 1e-12) {
        // Reversing, the arc is the same geometry driven backwards.
        cmd.omega_radps = cmd.v_mps * 2.0 * ty / d2;
      }
    }
    // Both wheels scaled down together when one is beyond the limit: the curvature is kept.
    return limitWheelSpeeds(toWheelSpeeds(cmd, robot_), robot_);
  }

 private:
  // The plan's pose lookahead_s after episode time t (at least min_lookahead_m ahead).
  parksim::Pose2 pointAhead(double t, double speed) const {
    const double start = plan_.points.front().t_s;
    const double dt = std::max(def_.lookahead_s, def_.min_lookahead_m / speed);
    const double when = start + t + dt;
    auto it =
        std::upper_bound(plan_.points.begin(), plan_.points.end(), when,
                         [](double v, const parksim::TrajectoryPoint& p) { return v < p.t_s; });
    if (it == plan_.points.begin()) return plan_.points.front().pose;
    const parksim::TrajectoryPoint& p = *(it - 1);
    if (it == plan_.points.end()) return p.pose;
    return parksim::integrateExact(p.pose, parksim::toTwist(p.wheels, robot_), when - p.t_s);
  }

  PurePursuitDef def_;
  parksim::RobotDef robot_;
  parksim::Trajectory plan_;
};

void bind(PurePursuitDef& d, parksim::ParamSet& s) {
  s.add("lookahead_s", &d.lookahead_s, "how far ahead on the plan the pursued point is, s", 0.0,
        100.0);
  s.add("min_lookahead_m", &d.min_lookahead_m, "the pursued point is at least this far, m", 1e-4,
        1e3);
  s.add("speed_gain", &d.speed_gain, "forward speed per metre of along-track error, 1/s", 0.0, 1e3);
  s.add("heading_gain", &d.heading_gain, "yaw rate per radian of heading error in turns, 1/s", 0.0,
        1e3);
}

}  // namespace

parksim::ControllerEntry purePursuit() {
  parksim::ControllerInfo info;
  info.name = "pure-pursuit";
  info.description = "pure pursuit of a point ahead on the plan (a plugin)";
  return parksim::controllerEntry<PurePursuit>(std::move(info), PurePursuitDef{}, &bind);
}

}  // namespace example
