#include "parksim/sim/episode/Episode.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>
#include <optional>
#include <string>
#include <utility>

#include "parksim/core/geometry/Angle.h"
#include "parksim/core/io/Error.h"
#include "parksim/core/io/NumberFormat.h"
#include "parksim/core/model/Ackermann.h"
#include "parksim/sim/control/TrackingController.h"
#include "parksim/sim/episode/ContactEvents.h"
#include "parksim/sim/episode/EpisodeStatistics.h"
#include "parksim/sim/episode/ParkedDisplacements.h"
#include "parksim/sim/episode/RealismLoop.h"
#include "parksim/sim/episode/ReferenceTrajectory.h"

namespace parksim {

namespace {

// Step counts from durations: a duration that is a whole number of steps up to rounding counts
// as that number, not one more.
long stepsFor(double duration_s, double dt_s) {
  return static_cast<long>(std::ceil(duration_s / dt_s - 1e-9));
}

const ExecutionDef& validated(const Scenario& scenario, const Trajectory& plan,
                              const ExecutionDef& def) {
  auto fail = [](const char* what) { throw Error(std::string("execution: ") + what); };
  if (!(def.rest_speed_mps > 0.0)) fail("rest_speed_mps must be positive");
  if (!(def.rest_yaw_rate_radps > 0.0)) fail("rest_yaw_rate_radps must be positive");
  if (!(def.rest_hold_s >= 0.0)) fail("rest_hold_s must not be negative");
  if (!(def.max_stop_time_s >= 0.0)) fail("max_stop_time_s must not be negative");
  if (!(def.contact_merge_s >= 0.0)) fail("contact_merge_s must not be negative");
  if (def.csv_stride_steps < 1) fail("csv_stride_steps must be at least 1");
  checkEpisodeLimits(scenario, plan, def);
  return def;
}

Trajectory shiftedPlan(const Trajectory& plan, const Pose2& origin) {
  Trajectory out = plan;
  for (TrajectoryPoint& p : out.points) {
    p.pose.x -= origin.x;
    p.pose.y -= origin.y;
  }
  return out;
}

// The model with the episode's robot as built and the ground sized to the plan.
SimModelDef modelFor(const SimModelDef& base, const Trajectory& plan, const RealismDef& r,
                     const RobotBuild& b, const Scenario& s) {
  SimModelDef m = base;
  if (!m.has_reach && !plan.points.empty()) {
    LotBounds reach{plan.points.front().pose.x, plan.points.front().pose.y,
                    plan.points.front().pose.x, plan.points.front().pose.y};
    for (const TrajectoryPoint& p : plan.points) {
      reach.x_min_m = std::min(reach.x_min_m, p.pose.x);
      reach.y_min_m = std::min(reach.y_min_m, p.pose.y);
      reach.x_max_m = std::max(reach.x_max_m, p.pose.x);
      reach.y_max_m = std::max(reach.y_max_m, p.pose.y);
    }
    m.has_reach = true;
    m.reach = reach;
  }
  return withRobotBuild(m, r, b, s);
}

}  // namespace

double checkEpisodeLimits(const Scenario& scenario, const Trajectory& plan,
                          const ExecutionDef& def) {
  if (plan.empty()) throw Error("execution: the plan is empty");
  const double dt = scenario.physics.time_step_s;
  const double duration = plan.duration();
  if (!(dt > 0.0) || !std::isfinite(dt))
    throw Error("execution: physics.time_step_s must be positive");
  if (!std::isfinite(plan.points.front().t_s) || !std::isfinite(duration) || duration < 0.0) {
    throw Error("execution: the plan's times must be finite and increasing");
  }
  // In double, so no duration or step reaches an out-of-range conversion to an integer.
  const double steps = std::ceil((duration + def.max_stop_time_s) / dt - 1e-9);
  if (!(steps <= def.max_steps)) {
    throw Error("execution: the episode needs " + formatGeneral(steps, 4) +
                " physics steps (plan " + formatGeneral(duration) + " s + stop " +
                formatGeneral(def.max_stop_time_s) + " s at physics.time_step_s " +
                formatGeneral(dt) + " s), more than the limit of " +
                formatGeneral(def.max_steps, 4) + " (docs/limits.md)");
  }
  return steps;
}

struct Episode::Impl {
  Impl(const Scenario& s, const Trajectory& plan, const ExecutionDef& d, const SimModelDef& m,
       EpisodeController c)
      : scenario(s),
        controller(std::move(c)),
        def(validated(s, plan, d)),
        build(drawRobotBuild(d.realism, d.noise_seed)),
        origin(localFrameOrigin(plan.points.front().pose, m.local_frame_grid_m)),
        reference(shiftedPlan(plan, origin), s.robot),
        world(s, plan.points.front().pose, modelFor(m, plan, d.realism, build, s)),
        dt(world.timeStep()),
        t0(reference.startTime()),
        plan_steps(stepsFor(reference.endTime() - reference.startTime(), dt)),
        limit_steps(plan_steps + stepsFor(d.max_stop_time_s, dt)),
        rest_steps(std::max(
            1L, stepsFor(d.realism.active() ? std::max(d.rest_hold_s, d.realism.control.settle_s)
                                            : d.rest_hold_s,
                         dt))),
        contacts(s.obstacles.size(), stepsFor(d.contact_merge_s, dt)),
        parked(s.obstacles, world.obstaclePoses()) {
    if (d.realism.active()) {
      validateRealism(d.realism);
      loop.emplace(d.realism, d.noise_seed, build, s.robot, plan.points.front().pose, dt);
    }
    if (!controller.controller) controller.controller = std::make_unique<TrackingController>();
    resetController(plan);
    measure(WheelSpeeds{});
  }

  Scenario scenario;
  EpisodeController controller;
  ExecutionDef def;
  RobotBuild build;
  // The plan and the controller live in the same lot-local frame as Bullet (DynamicsWorld),
  // so a lot far from the origin rounds like one at it; rows are in the lot frame.
  Pose2 origin;
  ReferenceTrajectory reference;
  DynamicsWorld world;
  double dt;
  double t0;
  long plan_steps;
  long limit_steps;
  long rest_steps;

  EpisodeStatistics statistics;
  ContactEventMerger contacts;
  ParkedDisplacements parked;
  std::optional<RealismLoop> loop;  // only when the realism is not ideal

  std::vector<ExecutedRow> rows;
  ExecutedRow current;
  std::string controller_error;
  // A car: the steering target of the steps from the last tick on, and the speed last
  // commanded (an acceleration command adds to it).
  double steer_cmd = 0.0;
  double car_speed_cmd = 0.0;
  // Encoder readings and time at the last control tick (the realism's measured wheel speeds).
  WheelSpeeds tick_encoders;
  double tick_t = 0.0;
  long steps_at_rest = 0;
  bool finished = false;
  bool at_rest = false;
  std::chrono::steady_clock::duration wall{};

  Pose2 local(const Pose2& p) const { return {p.x - origin.x, p.y - origin.y, p.theta}; }
  Pose2 lotFrame(const Pose2& p) const { return {p.x + origin.x, p.y + origin.y, p.theta}; }

  double planTime(long step) const { return t0 + static_cast<double>(step) * dt; }

  // The instant after the last step: the row, every measure, and whether the episode ends.
  void measure(const WheelSpeeds& command) {
    const long k = world.steps();
    const RobotState& state = world.robot();
    ExecutedRow row;
    row.t_s = static_cast<double>(k) * dt;
    row.pose = state.pose;
    row.reference = lotFrame(reference.poseAt(planTime(k)));
    row.wheels_cmd = command;
    row.wheels = state.wheels;
    row.pos_err_m = positionDistance(row.pose, row.reference);
    row.heading_err_rad = angleDiff(row.pose.theta, row.reference.theta);
    row.steer_ref_rad = reference.steerAt(planTime(k));
    row.steer_cmd_rad = world.steerTarget();
    row.steer_rad = state.steer_rad;
    row.estimate = row.pose;
    row.slip_mps = state.slip_mps;
    row.encoder_rad = state.wheel_angles;
    if (loop) {
      if (loop->def.estimator.kind != EstimatorKind::kTruth) row.estimate = loop->estimator.pose();
      row.est_pos_err_m = positionDistance(row.estimate, row.pose);
      row.est_heading_err_rad = angleDiff(row.estimate.theta, row.pose.theta);
      row.effort = loop->effort;
      row.torque_nm = loop->torque;
      row.encoder_rad = loop->encoder;
    }
    statistics.add(row, loop.has_value());
    current = row;
    contacts.add(k, row.t_s, world.chassisContacts(), scenario.obstacles);
    parked.update(world);

    if (k >= plan_steps) {
      const bool resting = std::abs(state.twist.v_mps) < def.rest_speed_mps &&
                           std::abs(state.twist.omega_radps) < def.rest_yaw_rate_radps;
      steps_at_rest = resting ? steps_at_rest + 1 : 0;
      if (steps_at_rest >= rest_steps) {
        finished = true;
        at_rest = true;
      }
    }
    if (k >= limit_steps) finished = true;
    if (k % def.csv_stride_steps == 0 || finished) rows.push_back(row);
  }

  void resetController(const Trajectory& plan) {
    ControllerSetup setup{scenario, plan};
    setup.period_s = loop ? loop->holdPeriod() : dt;
    setup.latency_s = loop ? loop->def.control.latency_s : 0.0;
    setup.estimated_pose = loop && loop->def.estimator.kind != EstimatorKind::kTruth;
    setup.ideal_robot = !loop;
    setup.time_limit_s = controller.time_limit_s;
    if (controller.trusted) {
      controller.controller->reset(setup);
      return;
    }
    guarded([&] { controller.controller->reset(setup); }, "reset");
  }

  // The controller's input at the step about to start. Wheel speeds are held per control
  // period; the middle of the interval the command acts over picks the plan's period without
  // depending on how k * dt rounds at a period boundary. Poses in the lot frame.
  ControllerInput controllerInput() {
    const long k = world.steps();
    const RobotState& state = world.robot();
    ControllerInput in;
    in.tick = loop ? loop->next_tick : k;
    in.t_s = static_cast<double>(k) * dt;
    in.reference = lotFrame(reference.poseAt(planTime(k)));
    in.plan_ended = k >= plan_steps;
    double act_mid = planTime(k) + 0.5 * dt;
    if (loop) {
      const RealismLoop& r = *loop;
      act_mid = planTime(k) + r.def.control.latency_s + 0.5 * r.holdPeriod();
      in.pose = r.def.estimator.kind == EstimatorKind::kTruth ? lotFrame(state.local_pose)
                                                              : r.estimator.pose();
      in.encoders_rad = r.encoder;
      const double since = in.t_s - tick_t;
      if (since > 0.0) {
        in.wheel_speeds_radps = {(r.encoder.left_radps - tick_encoders.left_radps) / since,
                                 (r.encoder.right_radps - tick_encoders.right_radps) / since};
      }
      tick_encoders = r.encoder;
      tick_t = in.t_s;
      in.twist = toTwist(in.wheel_speeds_radps, scenario.robot);
    } else {
      in.pose = lotFrame(state.local_pose);
      in.encoders_rad = state.wheel_angles;
      in.wheel_speeds_radps = state.wheels;
      in.twist = state.twist;
    }
    in.reference_twist = reference.twistAt(act_mid);
    in.feedforward = reference.wheelsAt(act_mid);
    in.steer_rad = state.steer_rad;
    in.reference_steer_rad = reference.steerTargetAt(act_mid);
    in.commanded_speed_mps = car_speed_cmd;
    return in;
  }

  // The command for the step about to start (the ideal robot), or at a realism's control tick:
  // the plan's wheel speeds open loop, the controller's closed loop.
  WheelSpeeds command() {
    if (def.tracking == TrackingMode::kOpen) {
      const long k = world.steps();
      const double mid = loop ? planTime(k) + loop->def.control.latency_s + 0.5 * loop->holdPeriod()
                              : planTime(k) + 0.5 * dt;
      steer_cmd = reference.steerTargetAt(mid);
      return reference.wheelsAt(mid);
    }
    const ControllerInput in = controllerInput();
    if (scenario.robot.isCar()) return carCommand(in);
    if (controller.trusted) return controller.controller->command(in);
    WheelSpeeds out;
    guarded([&] { out = controller.controller->command(in); }, "command");
    if (!controller_error.empty()) return {};
    return checkedWheels(out, in);
  }

  // A user's wheel speeds, or zero after recording why they are refused.
  WheelSpeeds checkedWheels(const WheelSpeeds& out, const ControllerInput& in) {
    const double limit = scenario.robot.max_wheel_speed_radps;
    const auto bad = [&](double w) { return !(std::abs(w) <= limit * (1.0 + 1e-9)); };
    if (bad(out.left_radps) || bad(out.right_radps)) {
      fail("returned (" + formatGeneral(out.left_radps, 6) + ", " +
           formatGeneral(out.right_radps, 6) + ") rad/s at t = " + formatFixed(in.t_s, 3) + " s: " +
           (std::isfinite(out.left_radps) && std::isfinite(out.right_radps)
                ? "beyond robot.max_wheel_speed_radps " + formatGeneral(limit)
                : std::string("not a number")));
      return {};
    }
    return out;
  }

  // A car's command (Controller.h): the controller's own, or its wheel speeds read as the rear
  // wheels'; a user's checked against the car's limits.
  WheelSpeeds carCommand(const ControllerInput& in) {
    std::optional<CarCommand> out;
    WheelSpeeds wheels;
    const auto ask = [&] {
      out = controller.controller->carCommand(in);
      if (!out) wheels = controller.controller->command(in);
    };
    if (controller.trusted) {
      ask();
    } else {
      guarded(ask, "command");
      if (!controller_error.empty()) return {};
      if (out && !withinCarLimits(*out, in.t_s)) return {};
      if (!out) {
        wheels = checkedWheels(wheels, in);
        if (!controller_error.empty()) return {};
      }
    }
    return applyCarCommand(out ? *out : carCommandOfWheels(wheels, scenario.robot, in.steer_rad));
  }

  // Whether a user's car command is finite and within the car's limits; records why not.
  bool withinCarLimits(const CarCommand& c, double t_s) {
    const RobotDef& car = scenario.robot;
    const auto check = [&](double value, double limit, const char* what, const char* field) {
      if (std::abs(value) <= limit * (1.0 + 1e-9)) return true;
      fail("returned " + std::string(what) + " " + formatGeneral(value, 6) +
           " at t = " + formatFixed(t_s, 3) + " s: " +
           (std::isfinite(value) ? "beyond robot." + std::string(field) + " " + formatGeneral(limit)
                                 : std::string("not a number")));
      return false;
    };
    const bool by_accel = c.mode == CarCommand::Mode::kAcceleration;
    return (by_accel ? check(c.accel_mps2, car.max_accel_mps2, "acceleration", "max_accel_mps2")
                     : check(c.speed_mps, car.max_speed_mps, "speed", "max_speed_mps")) &&
           check(c.steer_rad, car.max_steer_rad, "steering angle", "max_steer_rad");
  }

  // The car's command for the steps from this tick on: its steering target, and its rear
  // wheels at the commanded speed on the curvature its steering has now (an electronic
  // differential, Ackermann.h's carWheelSpeeds).
  WheelSpeeds applyCarCommand(const CarCommand& c) {
    const RobotDef& car = scenario.robot;
    const double period = loop ? loop->holdPeriod() : dt;
    const double v = c.mode == CarCommand::Mode::kAcceleration
                         ? car_speed_cmd + c.accel_mps2 * period
                         : c.speed_mps;
    car_speed_cmd = std::clamp(v, -car.max_speed_mps, car.max_speed_mps);
    steer_cmd = c.steer_rad;
    return limitWheelSpeeds(carWheelSpeeds(car, car_speed_cmd, world.robot().steer_rad), car);
  }

  // Runs a user's controller call; what it throws ends the episode with a controller error.
  template <class F>
  void guarded(F&& call, const char* what) {
    UserCodeWatch* watch = controller.watch;
    if (watch != nullptr) watch->enter(UserCodeWatch::Phase::kController, controller.name);
    try {
      call();
      if (watch != nullptr) watch->enter(UserCodeWatch::Phase::kParksim, "");
    } catch (const std::exception& e) {
      if (watch != nullptr) watch->enter(UserCodeWatch::Phase::kParksim, "");
      fail(std::string("threw in ") + what + " at t = " +
           formatFixed(static_cast<double>(world.steps()) * dt, 3) + " s: " + e.what());
    } catch (...) {
      if (watch != nullptr) watch->enter(UserCodeWatch::Phase::kParksim, "");
      fail(std::string("threw something that is not a std::exception in ") + what);
    }
  }

  void fail(const std::string& why) {
    if (controller_error.empty()) controller_error = "controller " + controller.name + " " + why;
  }

  // One step, driven by the tracking controller or by `external`: with a realism, `external`
  // replaces the controller's command at the control ticks and goes the same way (latency,
  // wheel-speed loop, motors).
  void advance(const std::optional<WheelSpeeds>& external,
               const std::optional<CarCommand>& external_car = std::nullopt) {
    const auto next = [&] {
      return external_car ? applyCarCommand(*external_car) : external ? *external : command();
    };
    if (loop) {
      const long k = world.steps();
      if (loop->controlDue(k)) {
        const WheelSpeeds cmd = next();
        if (endOnControllerError()) return;
        loop->tick(k, cmd);
        world.setSteerTarget(steer_cmd);
      }
      loop->actuate(k, world);
      world.step();
      loop->sense(world);
      measure(loop->setpoint);
    } else {
      const WheelSpeeds cmd = next();
      if (endOnControllerError()) return;
      world.setWheelTargets(cmd);
      world.setSteerTarget(steer_cmd);
      world.step();
      measure(cmd);
    }
    requireFiniteState();
  }

  // Physics far outside any real robot's range (gravity 1e300 m/s^2, wheels of 1e300 kg) makes
  // Bullet's state NaN within a step; every later number is then meaningless ("-nan mm", a max
  // error of 0). Say so once, where it happens.
  void requireFiniteState() const {
    const RobotState& state = world.robot();
    if (std::isfinite(state.pose.x) && std::isfinite(state.pose.y) &&
        std::isfinite(state.pose.theta)) {
      return;
    }
    throw Error("simulation: diverged at t = " + formatGeneral(planTime(world.steps()), 6) +
                " s (step " + std::to_string(world.steps()) +
                "): the robot's pose is no longer a finite number; the world's physics or robot "
                "values are outside what the simulation can integrate");
  }

  // A controller that failed ends the episode where it failed, the record kept.
  bool endOnControllerError() {
    if (controller_error.empty()) return false;
    finished = true;
    if (rows.empty() || rows.back().t_s != current.t_s) rows.push_back(current);
    return true;
  }

  void timed(const std::optional<WheelSpeeds>& external,
             const std::optional<CarCommand>& external_car = std::nullopt) {
    if (finished) return;
    const auto start = std::chrono::steady_clock::now();
    advance(external, external_car);
    wall += std::chrono::steady_clock::now() - start;
  }
};

Episode::Episode(const Scenario& scenario, const Trajectory& plan, const ExecutionDef& def,
                 const SimModelDef& model, EpisodeController controller) {
  if (plan.points.empty()) throw Error("simulation: the plan has no points");
  impl_ = std::make_unique<Impl>(scenario, plan, def, model, std::move(controller));
  impl_->endOnControllerError();  // a reset that failed
}

Episode::~Episode() = default;

void Episode::step() { impl_->timed(std::nullopt); }

void Episode::step(const WheelSpeeds& command) { impl_->timed(command); }

void Episode::step(const CarCommand& command) { impl_->timed(std::nullopt, command); }

WheelSpeeds Episode::controllerCommand() { return impl_->command(); }

bool Episode::finished() const { return impl_->finished; }

const ExecutedRow& Episode::current() const { return impl_->current; }

EpisodeSample Episode::sample() const {
  EpisodeSample s;
  s.tracking = current();
  s.obstacles = impl_->world.obstaclePoses();
  s.contacts = impl_->world.chassisContacts();
  s.stopping = impl_->world.steps() >= impl_->plan_steps;
  return s;
}

const std::vector<ExecutedRow>& Episode::rows() const { return impl_->rows; }

const std::vector<PoseMeasurement>& Episode::poseSamples() const {
  static const std::vector<PoseMeasurement> kNone;
  return impl_->loop ? impl_->loop->received : kNone;
}

EpisodeMetrics Episode::metrics() const {
  const Impl& d = *impl_;
  EpisodeMetrics m;
  m.tracking = d.def.tracking;
  m.controller = d.controller.name;
  m.controller_error = d.controller_error;
  d.statistics.report(m);
  m.final_pos_err_m = d.current.pos_err_m;
  m.final_heading_err_deg = radToDeg(std::abs(d.current.heading_err_rad));
  m.final_pose = d.current.pose;
  const GoalRegion& goal = d.scenario.goal;
  m.goal_pos_err_m = positionDistance(m.final_pose, goal.pose);
  const double goal_heading = goalHeadingError(goal, m.final_pose.theta);
  m.goal_heading_err_deg = radToDeg(goal_heading);
  m.goal_reached =
      m.goal_pos_err_m <= goal.position_tolerance_m && goal_heading <= goal.heading_tolerance_rad;
  m.contact_events = d.contacts.events();
  m.contacts = static_cast<int>(m.contact_events.size());
  if (!m.contact_events.empty()) {
    m.first_contact_t_s = m.contact_events.front().t_s;
    m.first_contact_body = m.contact_events.front().body;
  }
  m.parked = d.parked.all();
  m.max_parked_displacement_m = d.parked.max();
  m.plan_duration_s = d.reference.endTime() - d.reference.startTime();
  m.steps = d.world.steps();
  m.time_step_s = d.dt;
  m.sim_time_s = d.current.t_s;
  m.ended_at_rest = d.at_rest;
  m.wall_time_s = std::chrono::duration<double>(d.wall).count();

  m.realism = d.def.realism.name;
  m.noise_seed = d.def.noise_seed;
  m.estimator = toString(d.def.realism.estimator.kind);
  m.final_est_pos_err_m = d.current.est_pos_err_m;
  m.true_left_radius_m = d.world.leftWheelRadius();
  m.true_right_radius_m = d.world.rightWheelRadius();
  m.true_track_m = d.world.track();
  m.left_motor_gain = d.build.left_gain;
  m.right_motor_gain = d.build.right_gain;
  if (d.loop) {
    m.pose_samples_taken = d.loop->sensor.taken();
    m.pose_samples_dropped = d.loop->sensor.dropped() + d.loop->dropped_late;
    m.pose_samples_received = static_cast<long>(d.loop->received.size());
  }
  return m;
}

const DynamicsWorld& Episode::world() const { return impl_->world; }

}  // namespace parksim
