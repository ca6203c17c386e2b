// `my-controller`: the code under test. It follows the plan's speeds, corrects the speed by the
// along-track error and the yaw rate by the heading and cross-track errors, with gains a sweep
// can vary (`set: {controller.heading_gain: [...]}`). Wheel speeds are scaled into the robot's
// limit.

#include <cmath>

#include <parksim/sim/control/TrackingController.h>
#include <parksim/usercode/PluginApi.h>

namespace {

struct MyControllerDef {
  double speed_gain = 4.0;      ///< forward speed per metre of along-track error, 1/s
  double heading_gain = 6.0;    ///< yaw rate per radian of heading error, 1/s
  double lateral_gain = 400.0;  ///< yaw rate per metre of cross-track error per m/s, 1/(m s)
};

class MyController : public parksim::Controller {
 public:
  explicit MyController(const MyControllerDef& def) : def_(def) {}

  void reset(const parksim::ControllerSetup& setup) override { robot_ = setup.scenario.robot; }

  parksim::WheelSpeeds command(const parksim::ControllerInput& in) override {
    using namespace parksim;
    // Past the plan's end the reference holds its last pose (at rest): the same law parks.
    const Pose2& p = in.pose;
    // The reference's offset ahead of the robot and to its left.
    const double ex =
        std::cos(p.theta) * (in.reference.x - p.x) + std::sin(p.theta) * (in.reference.y - p.y);
    const double ey =
        -std::sin(p.theta) * (in.reference.x - p.x) + std::cos(p.theta) * (in.reference.y - p.y);
    const double eth = std::remainder(in.reference.theta - p.theta, 2.0 * M_PI);
    const double v = in.reference_twist.v_mps;
    const Twist cmd{
        v + def_.speed_gain * ex,
        in.reference_twist.omega_radps + def_.heading_gain * eth + def_.lateral_gain * v * ey};
    // Both wheels scaled down together when one is beyond the limit: the curvature is kept.
    return limitWheelSpeeds(toWheelSpeeds(cmd, robot_), robot_);
  }

 private:
  MyControllerDef def_;
  parksim::RobotDef robot_;
};

void bind(MyControllerDef& d, parksim::ParamSet& s) {
  s.add("speed_gain", &d.speed_gain, "forward speed per metre of along-track error, 1/s", 0.0, 1e3);
  s.add("heading_gain", &d.heading_gain, "yaw rate per radian of heading error, 1/s", 0.0, 1e3);
  s.add("lateral_gain", &d.lateral_gain, "yaw rate per metre of cross-track error per m/s", 0.0,
        1e5);
}

void registerComponents(parksim::PluginRegistrar& r) {
  parksim::ControllerInfo info;
  info.name = "my-controller";
  info.description = "heading and cross-track correction on the plan's wheel speeds";
  r.addController(
      parksim::controllerEntry<MyController>(std::move(info), MyControllerDef{}, &bind));
}

}  // namespace

PARKSIM_PLUGIN("my-controller", "0.1.0", registerComponents)
