#include "parksim/sim/Episode.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <deque>
#include <optional>
#include <random>
#include <utility>

#include "parksim/core/Angle.h"
#include "parksim/core/Error.h"
#include "parksim/core/NumberFormat.h"
#include "parksim/sim/ReferenceTrajectory.h"
#include "parksim/sim/TrackingController.h"

namespace parksim {

namespace {

// Step counts from durations: a duration that is a whole number of steps up to rounding counts
// as that number, not one more.
long stepsFor(double duration_s, double dt_s) {
  return static_cast<long>(std::ceil(duration_s / dt_s - 1e-9));
}

double goalHeadingError(const GoalRegion& goal, double theta) {
  double err = std::abs(angleDiff(theta, goal.pose.theta));
  if (goal.either_heading) err = std::min(err, std::abs(angleDiff(theta, goal.pose.theta + kPi)));
  return err;
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

// One generator per realism layer, seeded by (noise seed, layer): a layer switched off or
// changed does not shift another layer's draws.
std::mt19937_64 layerRng(std::uint64_t noise_seed, std::uint32_t layer) {
  std::seed_seq seq{static_cast<std::uint32_t>(noise_seed & 0xffffffffU),
                    static_cast<std::uint32_t>(noise_seed >> 32U), layer};
  return std::mt19937_64(seq);
}

Pose2 localOrigin(const Pose2& start, double grid_m) {
  return {grid_m * std::floor(start.x / grid_m), grid_m * std::floor(start.y / grid_m), 0.0};
}

Trajectory shiftedPlan(const Trajectory& plan, const Pose2& origin) {
  Trajectory out = plan;
  for (TrajectoryPoint& p : out.points) {
    p.pose.x -= origin.x;
    p.pose.y -= origin.y;
  }
  return out;
}

enum Layer : std::uint32_t { kCalibrationLayer = 1, kMotorLayer, kEncoderLayer, kPoseLayer };

// The robot as built for this episode: calibration errors and motor gains drawn once.
struct Build {
  double left_scale = 1.0;
  double right_scale = 1.0;
  double track_scale = 1.0;
  double left_gain = 1.0;
  double right_gain = 1.0;
};

Build drawBuild(const RealismDef& r, std::uint64_t seed) {
  Build b;
  if (!r.active()) return b;
  std::mt19937_64 rng = layerRng(seed, kCalibrationLayer);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const CalibrationDef& c = r.calibration;
  // Always three draws in this order, so a range of zero keeps the others' values.
  const double dl = u(rng);
  const double dr = u(rng);
  const double dt = u(rng);
  b.left_scale = 1.0 + 0.01 * (c.left_radius_error_pct + c.radius_error_range_pct * dl);
  b.right_scale = 1.0 + 0.01 * (c.right_radius_error_pct + c.radius_error_range_pct * dr);
  b.track_scale = 1.0 + 0.01 * (c.track_error_pct + c.track_error_range_pct * dt);
  if (r.motor.enabled) {
    std::mt19937_64 motor_rng = layerRng(seed, kMotorLayer);
    b.left_gain = drawMotorGain(r.motor, motor_rng);
    b.right_gain = drawMotorGain(r.motor, motor_rng);
  }
  return b;
}

// The model with the episode's robot as built and the ground sized to the plan.
SimModelDef modelFor(const SimModelDef& base, const Trajectory& plan, const RealismDef& r,
                     const Build& b, const Scenario& s) {
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
  if (!r.active()) return m;
  m.body.left_radius_scale = b.left_scale;
  m.body.right_radius_scale = b.right_scale;
  m.body.track_scale = b.track_scale;
  if (r.motor.enabled) {
    const MotorModel motor(r.motor, 1.0);
    m.body.drive = WheelDrive::kTorque;
    m.body.wheel_axle_inertia_kgm2 = motor.axleInertia();
    const double weight_per_wheel =
        0.5 * s.physics.gravity_mps2 *
        (s.physics.chassis_mass_kg + 2.0 * s.physics.wheel_mass_kg + base.support_mass_kg);
    m.body.joint_friction_nm = motor.frictionTorque() + r.motor.rolling_resistance *
                                                            weight_per_wheel *
                                                            s.robot.wheel_radius_m;
  }
  return m;
}

}  // namespace

// Everything between the controller and the physics when the realism is not ideal.
struct RealismLoop {
  RealismLoop(const RealismDef& d, std::uint64_t seed, const Build& b, const RobotDef& nominal,
              const Pose2& start, double dt_s)
      : def(d),
        build(b),
        encoder_rng(layerRng(seed, kEncoderLayer)),
        pose_rng(layerRng(seed, kPoseLayer)),
        left_motor(d.motor, b.left_gain),
        right_motor(d.motor, b.right_gain),
        left_loop(d.wheel_loop, d.motor.no_load_speed_radps, d.motor.supply_limit),
        right_loop(d.wheel_loop, d.motor.no_load_speed_radps, d.motor.supply_limit),
        left_encoder(d.encoder),
        right_encoder(d.encoder),
        sensor(d.pose_sensor, dt_s),
        estimator(d.estimator, nominal, d.pose_sensor, start),
        radius(nominal.wheel_radius_m),
        dt(dt_s),
        latency_steps(std::lround(d.control.latency_s / dt_s)),
        wheel_loop_steps(std::max(1L, std::lround(1.0 / (d.wheel_loop.rate_hz * dt_s)))) {}

  RealismDef def;
  Build build;
  std::mt19937_64 encoder_rng;
  std::mt19937_64 pose_rng;
  MotorModel left_motor;
  MotorModel right_motor;
  WheelSpeedLoop left_loop;
  WheelSpeedLoop right_loop;
  Encoder left_encoder;
  Encoder right_encoder;
  PoseSensor sensor;
  Estimator estimator;
  double radius;  // nominal
  double dt;
  long latency_steps;
  long wheel_loop_steps;

  long next_tick = 0;                                // index of the next control tick
  std::deque<std::pair<long, WheelSpeeds>> pending;  // set-points and the step they arrive
  WheelSpeeds setpoint;
  WheelSpeeds effort;
  WheelSpeeds torque;
  WheelSpeeds encoder;          // last encoder readings, rad
  WheelSpeeds encoder_at_loop;  // readings at the wheel loop's last tick, rad
  std::vector<PoseMeasurement> received;
  long dropped_late = 0;

  bool controlDue(long k) const {
    if (def.control.rate_hz <= 0.0) return true;
    return static_cast<double>(k) * dt >=
           static_cast<double>(next_tick) / def.control.rate_hz - 1e-9 * dt;
  }
  void advanceTick(long k) {
    if (def.control.rate_hz <= 0.0) return;
    while (static_cast<double>(next_tick) / def.control.rate_hz - 1e-9 * dt <=
           static_cast<double>(k) * dt) {
      ++next_tick;
    }
  }
  double holdPeriod() const { return def.control.rate_hz > 0.0 ? 1.0 / def.control.rate_hz : dt; }
};
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
  Impl(const Scenario& s, const Trajectory& plan, const ExecutionDef& d, const SimModelDef& m)
      : scenario(s),
        def(validated(s, plan, d)),
        build(drawBuild(d.realism, d.noise_seed)),
        origin(localOrigin(plan.points.front().pose, m.local_frame_grid_m)),
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
        merge_steps(stepsFor(d.contact_merge_s, dt)),
        last_contact_step(s.obstacles.size(), -1) {
    initial_obstacles = world.obstaclePoses();
    parked_slot.assign(s.obstacles.size(), -1);
    for (std::size_t i = 0; i < s.obstacles.size(); ++i) {
      if (s.obstacles[i].kind == ObstacleKind::kParkedRobot) {
        parked_slot[i] = static_cast<int>(parked.size());
        parked.push_back({s.obstacles[i].name, 0.0, 0.0});
      }
    }
    if (d.realism.active()) {
      validateRealism(d.realism);
      loop.emplace(d.realism, d.noise_seed, build, s.robot, plan.points.front().pose, dt);
    }
    measure(WheelSpeeds{});
  }

  Scenario scenario;
  ExecutionDef def;
  Build build;
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
  long merge_steps;

  std::vector<Pose2> initial_obstacles;
  std::vector<int> parked_slot;  // per obstacle: index into parked, -1 if not a parked robot
  std::vector<ParkedRobotDisplacement> parked;
  std::optional<RealismLoop> loop;  // only when the realism is not ideal

  std::vector<ExecutedRow> rows;
  ExecutedRow current;
  std::vector<long> last_contact_step;  // per obstacle; -1: never touched
  std::vector<ContactEvent> contact_events;
  double sum_sq_pos = 0.0;
  double sum_sq_heading = 0.0;
  double max_pos = 0.0;
  double max_heading = 0.0;
  double max_est_pos = 0.0;
  double sum_sq_est_pos = 0.0;
  double max_est_heading = 0.0;
  double max_slip = 0.0;
  double sum_sq_slip = 0.0;
  long slipping = 0;
  double max_torque = 0.0;
  double max_effort = 0.0;
  long measured = 0;
  long steps_at_rest = 0;
  bool finished = false;
  bool at_rest = false;
  std::chrono::steady_clock::duration wall{};

  Pose2 local(const Pose2& p) const { return {p.x - origin.x, p.y - origin.y, p.theta}; }
  Pose2 lotFrame(const Pose2& p) const { return {p.x + origin.x, p.y + origin.y, p.theta}; }

  double planTime(long step) const { return t0 + static_cast<double>(step) * dt; }

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
      max_est_pos = std::max(max_est_pos, row.est_pos_err_m);
      sum_sq_est_pos += row.est_pos_err_m * row.est_pos_err_m;
      max_est_heading = std::max(max_est_heading, std::abs(row.est_heading_err_rad));
      max_torque = std::max(
          {max_torque, std::abs(row.torque_nm.left_radps), std::abs(row.torque_nm.right_radps)});
      max_effort =
          std::max({max_effort, std::abs(row.effort.left_radps), std::abs(row.effort.right_radps)});
    }
    for (double slip : {state.slip_mps.left_radps, state.slip_mps.right_radps}) {
      max_slip = std::max(max_slip, std::abs(slip));
      sum_sq_slip += slip * slip;
      if (std::abs(slip) > 1e-3) ++slipping;
    }
    current = row;

    max_pos = std::max(max_pos, row.pos_err_m);
    max_heading = std::max(max_heading, std::abs(row.heading_err_rad));
    sum_sq_pos += row.pos_err_m * row.pos_err_m;
    sum_sq_heading += row.heading_err_rad * row.heading_err_rad;
    ++measured;

    for (int index : world.chassisContacts()) {
      long& last = last_contact_step[static_cast<std::size_t>(index)];
      if (last < 0 || k - last > merge_steps) {
        contact_events.push_back(
            {row.t_s, index, scenario.obstacles[static_cast<std::size_t>(index)].name});
      }
      last = k;
    }

    // Only parked robots that have mass can have moved (the others are fixed bodies): far
    // ones cost nothing per step. Positions only: no allocation and no heading per step.
    for (int index : world.movableObstacles()) {
      const auto i = static_cast<std::size_t>(index);
      const Eigen::Vector2d p = world.obstaclePosition(i);
      const double d = positionDistance({p.x(), p.y(), 0.0}, initial_obstacles[i]);
      ParkedRobotDisplacement& slot = parked[static_cast<std::size_t>(parked_slot[i])];
      slot.final_m = d;
      slot.max_m = std::max(slot.max_m, d);
    }

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

  // The realism controller's command at a control tick: from its estimate (or the truth),
  // held from the tick plus the latency for one hold period.
  WheelSpeeds realismCommand() const {
    const RealismLoop& r = *loop;
    const long k = world.steps();
    const double hold_mid = planTime(k) + r.def.control.latency_s + 0.5 * r.holdPeriod();
    if (def.tracking == TrackingMode::kOpen) return reference.wheelsAt(hold_mid);
    const Pose2 estimate = r.def.estimator.kind == EstimatorKind::kTruth
                               ? world.robot().local_pose
                               : local(r.estimator.pose());
    return trackingCommand(estimate, reference.poseAt(planTime(k)), reference.twistAt(hold_mid),
                           def.gains, scenario.robot);
  }

  // The realism's step: control tick (estimate -> set-points, delivered after the latency),
  // wheel-speed loop and motors, physics, then encoders, odometry, the pose sensor and the
  // estimator's corrections, in that order.
  // `external`: a command from outside (Episode::step(command)) replaces the controller's at
  // the control ticks and goes the same way (latency, wheel-speed loop, motors).
  void realismStep(const std::optional<WheelSpeeds>& external) {
    RealismLoop& r = *loop;
    const long k = world.steps();
    if (r.controlDue(k)) {
      r.pending.emplace_back(k + r.latency_steps, external ? *external : realismCommand());
      r.advanceTick(k);
    }
    while (!r.pending.empty() && r.pending.front().first <= k) {
      r.setpoint = r.pending.front().second;
      r.pending.pop_front();
    }
    if (r.def.motor.enabled) {
      if (k % r.wheel_loop_steps == 0) {
        const double period = static_cast<double>(r.wheel_loop_steps) * dt;
        // Speed from the encoder's count difference over the loop's period; the first tick
        // has no earlier count.
        const WheelSpeeds speed =
            k == 0 ? WheelSpeeds{}
                   : WheelSpeeds{(r.encoder.left_radps - r.encoder_at_loop.left_radps) / period,
                                 (r.encoder.right_radps - r.encoder_at_loop.right_radps) / period};
        r.encoder_at_loop = r.encoder;
        r.effort = {r.left_loop.update(r.setpoint.left_radps, speed.left_radps, period),
                    r.right_loop.update(r.setpoint.right_radps, speed.right_radps, period)};
      }
      const WheelSpeeds& omega = world.robot().wheels;
      r.torque = {r.left_motor.torque(r.effort.left_radps, omega.left_radps),
                  r.right_motor.torque(r.effort.right_radps, omega.right_radps)};
      world.setWheelTorques(r.torque);
    } else {
      world.setWheelTargets(r.setpoint);
    }
    world.step();
    const long now = world.steps();
    const RobotState& state = world.robot();
    const WheelSpeeds before = r.encoder;
    r.encoder = {r.left_encoder.read(state.wheel_angles.left_radps, r.encoder_rng),
                 r.right_encoder.read(state.wheel_angles.right_radps, r.encoder_rng)};
    r.estimator.predict(now, r.radius * (r.encoder.left_radps - before.left_radps),
                        r.radius * (r.encoder.right_radps - before.right_radps));
    r.sensor.observe(now, state.pose, r.pose_rng);
    for (const PoseMeasurement& m : r.sensor.deliver(now)) {
      if (r.estimator.correct(m)) {
        r.received.push_back(m);
      } else {
        ++r.dropped_late;
      }
    }
    measure(r.setpoint);
  }

  // One step, driven by the tracking controller or by `external`.
  void advance(const std::optional<WheelSpeeds>& external) {
    if (loop) {
      realismStep(external);
    } else {
      const WheelSpeeds cmd = external ? *external : command();
      world.setWheelTargets(cmd);
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

  WheelSpeeds command() const {
    const long k = world.steps();
    // Wheel speeds are held per control period; the step's midpoint picks the period without
    // depending on how k * dt rounds at a period boundary.
    const double mid = planTime(k) + 0.5 * dt;
    if (def.tracking == TrackingMode::kOpen) return reference.wheelsAt(mid);
    return trackingCommand(world.robot().local_pose, reference.poseAt(planTime(k)),
                           reference.twistAt(mid), def.gains, scenario.robot);
  }
};

Episode::Episode(const Scenario& scenario, const Trajectory& plan, const ExecutionDef& def,
                 const SimModelDef& model) {
  if (plan.points.empty()) throw Error("simulation: the plan has no points");
  impl_ = std::make_unique<Impl>(scenario, plan, def, model);
}

Episode::~Episode() = default;

void Episode::step() {
  Impl& d = *impl_;
  if (d.finished) return;
  const auto start = std::chrono::steady_clock::now();
  d.advance(std::nullopt);
  d.wall += std::chrono::steady_clock::now() - start;
}

void Episode::step(const WheelSpeeds& command) {
  Impl& d = *impl_;
  if (d.finished) return;
  const auto start = std::chrono::steady_clock::now();
  d.advance(command);
  d.wall += std::chrono::steady_clock::now() - start;
}

WheelSpeeds Episode::controllerCommand() const {
  return impl_->loop ? impl_->realismCommand() : impl_->command();
}

bool Episode::finished() const { return impl_->finished; }

EpisodeSample Episode::sample() const {
  EpisodeSample s;
  s.tracking = impl_->current;
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
  m.max_pos_err_m = d.max_pos;
  m.rms_pos_err_m = std::sqrt(d.sum_sq_pos / static_cast<double>(d.measured));
  m.final_pos_err_m = d.current.pos_err_m;
  m.max_heading_err_deg = radToDeg(d.max_heading);
  m.rms_heading_err_deg = radToDeg(std::sqrt(d.sum_sq_heading / static_cast<double>(d.measured)));
  m.final_heading_err_deg = radToDeg(std::abs(d.current.heading_err_rad));
  m.final_pose = d.current.pose;
  const GoalRegion& goal = d.scenario.goal;
  m.goal_pos_err_m = positionDistance(m.final_pose, goal.pose);
  const double goal_heading = goalHeadingError(goal, m.final_pose.theta);
  m.goal_heading_err_deg = radToDeg(goal_heading);
  m.goal_reached =
      m.goal_pos_err_m <= goal.position_tolerance_m && goal_heading <= goal.heading_tolerance_rad;
  m.contact_events = d.contact_events;
  m.contacts = static_cast<int>(d.contact_events.size());
  if (!d.contact_events.empty()) {
    m.first_contact_t_s = d.contact_events.front().t_s;
    m.first_contact_body = d.contact_events.front().body;
  }
  m.parked = d.parked;
  for (const ParkedRobotDisplacement& p : d.parked) {
    m.max_parked_displacement_m = std::max(m.max_parked_displacement_m, p.max_m);
  }
  m.plan_duration_s = d.reference.endTime() - d.reference.startTime();
  m.steps = d.world.steps();
  m.time_step_s = d.dt;
  m.sim_time_s = d.current.t_s;
  m.ended_at_rest = d.at_rest;
  m.wall_time_s = std::chrono::duration<double>(d.wall).count();

  m.realism = d.def.realism.name;
  m.noise_seed = d.def.noise_seed;
  m.estimator = toString(d.def.realism.estimator.kind);
  const auto n = static_cast<double>(d.measured);
  m.max_est_pos_err_m = d.max_est_pos;
  m.rms_est_pos_err_m = std::sqrt(d.sum_sq_est_pos / n);
  m.max_est_heading_err_deg = radToDeg(d.max_est_heading);
  m.final_est_pos_err_m = d.current.est_pos_err_m;
  m.max_slip_mps = d.max_slip;
  m.rms_slip_mps = std::sqrt(d.sum_sq_slip / (2.0 * n));
  m.slip_fraction = static_cast<double>(d.slipping) / (2.0 * n);
  m.max_motor_torque_nm = d.max_torque;
  m.max_motor_effort = d.max_effort;
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

EpisodeResult runEpisode(const Scenario& scenario, const Trajectory& plan, const ExecutionDef& def,
                         const EpisodeObserver& observer, double observer_period_s) {
  Episode episode(scenario, plan, def);
  if (observer) {
    if (!(observer_period_s > 0.0)) throw Error("execution: observer period must be positive");
    observer(episode.sample());
  }
  const double dt = episode.world().timeStep();
  long next_observation = 1;  // index of the next period boundary to report
  while (!episode.finished()) {
    episode.step();
    if (!observer) continue;
    const long k = episode.world().steps();
    const bool due = static_cast<double>(k) * dt >=
                     static_cast<double>(next_observation) * observer_period_s - 1e-9 * dt;
    if (due || episode.finished()) {
      observer(episode.sample());
      while (static_cast<double>(next_observation) * observer_period_s - 1e-9 * dt <=
             static_cast<double>(k) * dt) {
        ++next_observation;
      }
    }
  }
  return {episode.metrics(), episode.rows(), episode.poseSamples()};
}

}  // namespace parksim
