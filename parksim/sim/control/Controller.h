#pragma once
// The one controller interface (nav2's Controller: setPlan, then computeVelocityCommands every
// cycle): reset with the plan and the world, then at every control tick what the robot knows
// in, left and right wheel speed commands out. parksim's tracking controller
// (TrackingController.h) implements it exactly as a user's controller does, and is found by
// name in a ControllerRegistry (ControllerRegistry.h), built in or loaded from a plugin.
//
// Ticks: with the ideal robot, every physics step (240 Hz by default), on the true pose; under
// a realism (realism/RealismDef.h), at its control rate, on the estimator's pose, and each
// command then goes the realism's way: latency, the wheel-speed loop, the motors. The same
// controller runs under both without knowing which.
//
//   class Stop : public parksim::Controller {
//    public:
//     void reset(const parksim::ControllerSetup&) override {}
//     parksim::WheelSpeeds command(const parksim::ControllerInput& in) override {
//       return in.plan_ended ? parksim::WheelSpeeds{} : in.feedforward;  // open loop
//     }
//   };
//
// Commands are wheel angular speeds, rad/s, each within the robot's max_wheel_speed_radps. A
// controller that is not built in and throws, returns a value that is not finite or outside
// that limit is a controller_error (pipeline/Verdict.h), not an input error.
//
// A car (RobotDef::isCar, docs/cars.md) is asked carCommand() instead: a speed of its reference
// point (or an acceleration) and a steering angle, checked against max_speed_mps,
// max_accel_mps2 and max_steer_rad the same way. Its rear wheels are then driven at that speed
// on the curvature of the steering angle measured at the tick (an electronic differential:
// Ackermann.h's carWheelSpeeds), and its steering turns toward the angle at most
// max_steer_rate_radps. The default carCommand() reads command()'s wheel speeds as a car's rear
// wheels, so a controller written for the differential drive also drives a car.

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <optional>

#include "parksim/core/geometry/Pose2.h"
#include "parksim/core/model/DiffDrive.h"
#include "parksim/core/model/Scenario.h"
#include "parksim/core/model/Trajectory.h"
#include "parksim/core/params/ComponentRegistry.h"
#include "parksim/core/params/ParamMap.h"
#include "parksim/core/params/ParamSet.h"

namespace parksim {

/// The default controller: parksim's tracking controller (TrackingController.h).
inline constexpr const char* kDefaultController = "tracking";

/// What a controller is told before the first tick of an episode; valid until the episode ends.
struct ControllerSetup {
  /// The robot as the controller believes it to be (nominal wheel base, radius and limits; the
  /// robot as built may differ under a realism), the lot, the obstacles and the goal region.
  const Scenario& scenario;
  /// The plan to follow, in the lot frame, on the plan's clock: episode time t is plan time
  /// plan.points.front().t_s + t.
  const Trajectory& plan;
  /// Time between ticks, s: the physics step with the ideal robot, the realism's control
  /// period otherwise.
  double period_s = 0.0;
  /// A command takes effect this long after its tick (the realism's control latency), s.
  double latency_s = 0.0;
  /// True when ControllerInput::pose is an estimate (a realism with an estimator), false when
  /// it is the true pose.
  bool estimated_pose = false;
  /// True for the ideal robot (no realism active): the input's pose, twist and wheel speeds are
  /// the truth, and every physics step is a tick.
  bool ideal_robot = true;
  /// The run's limit on one command of a user's controller, its reset included, s
  /// (UserCodeLimits::controller_tick_s, `--controller-timeout`; 0: none): the watch of a
  /// worker process enforces it on code in parksim's process, and a controller that runs a
  /// process of its own (the command controller) gives up on the process at it.
  double time_limit_s = 0.0;
};

/// What the robot knows at one control tick. Poses are in the lot frame.
struct ControllerInput {
  long tick = 0;     ///< 0 at the episode's start, then 1, 2, ...
  double t_s = 0.0;  ///< episode time of the tick, s
  Pose2 pose;        ///< the true pose, or the estimator's estimate under a realism
  /// The encoders' wheel angles, rad (quantised and noisy under a realism).
  WheelSpeeds encoders_rad;
  /// Measured wheel speeds, rad/s: the true speeds with the ideal robot; under a realism the
  /// encoders' difference over the last control period.
  WheelSpeeds wheel_speeds_radps;
  /// The body's (v, omega): the true twist with the ideal robot; under a realism the twist of
  /// the measured wheel speeds (nominal radius and wheel base).
  Twist twist;
  Pose2 reference;  ///< the plan's pose at t_s
  /// The plan's twist and wheel speeds over the interval this tick's command will act (from
  /// the tick plus the latency, for one period): the feed-forward.
  Twist reference_twist;
  WheelSpeeds feedforward;
  bool plan_ended = false;  ///< past the plan's end: the reference is its last pose, at rest
  // A car (RobotDef::isCar; 0 for a differential drive):
  /// Its measured steering angle (the bicycle angle of its front wheels' angles), rad.
  double steer_rad = 0.0;
  /// The plan's steering angle to aim at over the interval this tick's command will act (the
  /// next point's angle from half the time its change takes before it, so that a steering
  /// turning at its rate limit is centred on the plan's change: the feed-forward), rad.
  double reference_steer_rad = 0.0;
  /// The speed it was commanded at the last tick (what an acceleration command adds to), m/s.
  double commanded_speed_mps = 0.0;
};

/// A car's command (RobotDef::isCar).
struct CarCommand {
  enum class Mode {
    kSpeed,         ///< drive the reference point at speed_mps
    kAcceleration,  ///< change the commanded speed by accel_mps2 for one control period
  };
  Mode mode = Mode::kSpeed;
  /// Speed of the reference point (the rear axle's middle) along the heading, m/s; negative
  /// reverses. Within +-max_speed_mps.
  double speed_mps = 0.0;
  /// kAcceleration: rate of change of the commanded speed, m/s^2, within +-max_accel_mps2.
  double accel_mps2 = 0.0;
  /// Front-wheel angle of the bicycle model to steer toward, rad, left positive, within
  /// +-max_steer_rad.
  double steer_rad = 0.0;
};

class Controller {
 public:
  virtual ~Controller() = default;

  /// Called once before the first tick, with the plan to follow.
  virtual void reset(const ControllerSetup& setup) = 0;
  /// The wheel speed commands for this tick, rad/s.
  virtual WheelSpeeds command(const ControllerInput& input) = 0;
  /// A car's command for this tick, or nothing (the default): the car is then driven by
  /// command()'s wheel speeds read as its rear wheels' (carCommandOfWheels).
  virtual std::optional<CarCommand> carCommand(const ControllerInput& /*input*/) {
    return std::nullopt;
  }
};

/// Wheel speeds read as a car's rear wheels': the speed of their mean rim speed, the steering
/// angle of their curvature (`measured_steer_rad` while they stand still: below 1 mm/s the
/// curvature is noise), both clamped to the car's limits.
CarCommand carCommandOfWheels(const WheelSpeeds& wheels, const RobotDef& car,
                              double measured_steer_rad);

/// What the registry knows of a controller besides how to make one.
struct ControllerInfo {
  std::string name;               ///< registered name, as --controller and sweep specs write it
  std::string description;        ///< one line, for help texts
  std::vector<ParamInfo> params;  ///< its declared parameters (ParamSet.h)
  /// Set by the entry: the controller runs code parksim does not own (a process, a Python
  /// object), so it is not trusted even when registered without a plugin.
  bool runs_user_code = false;
  /// Set by the entry: that user code runs in a process of its own, with time limits of its
  /// own (a command): parksim's process needs no watch for it (UserCodeIsolation.h).
  bool own_process = false;
  /// Set by the registry: parksim's own code. Any other controller's commands are checked
  /// (finite, within the wheel-speed limit) and its failures are controller_error.
  bool trusted = false;
  std::string plugin;  ///< the plugin that registered it ("" for built-ins)
};

/// Makes a controller with its parameters applied; throws Error on a bad parameter.
using ControllerFactory = std::function<std::unique_ptr<Controller>(const ParamMap& params)>;

struct ControllerEntry {
  static constexpr const char* kKind = "controller";
  ControllerInfo info;
  ControllerFactory make;
};

/// A ControllerEntry whose controller type C is constructed as C(def) from a Def struct D whose
/// parameters `bind` declares (as plannerEntry, planner/base/Planner.h).
template <class C, class D>
ControllerEntry controllerEntry(ControllerInfo info, D def, void (*bind)(D&, ParamSet&)) {
  const std::string owner = "controller " + info.name;
  info.params = declaredParams(owner, def, bind);
  return {std::move(info), boundFactory<Controller, C>(owner, std::move(def), bind)};
}

/// Controllers by name (ComponentRegistry.h).
using ControllerRegistry = ComponentRegistry<ControllerEntry>;

/// parksim's own controllers: tracking (TrackingController.h), the default. Built once, never
/// changed.
const ControllerRegistry& builtInControllers();

}  // namespace parksim
