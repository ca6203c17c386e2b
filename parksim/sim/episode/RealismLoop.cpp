#include "parksim/sim/episode/RealismLoop.h"

#include <algorithm>
#include <cmath>

namespace parksim {

namespace {

enum Layer : std::uint32_t { kCalibrationLayer = 1, kMotorLayer, kEncoderLayer, kPoseLayer };

std::mt19937_64 layerRng(std::uint64_t noise_seed, std::uint32_t layer) {
  std::seed_seq seq{static_cast<std::uint32_t>(noise_seed & 0xffffffffU),
                    static_cast<std::uint32_t>(noise_seed >> 32U), layer};
  return std::mt19937_64(seq);
}

}  // namespace

RobotBuild drawRobotBuild(const RealismDef& r, std::uint64_t seed) {
  RobotBuild b;
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

SimModelDef withRobotBuild(SimModelDef m, const RealismDef& r, const RobotBuild& b,
                           const Scenario& s) {
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
        (s.physics.chassis_mass_kg + 2.0 * s.physics.wheel_mass_kg + m.support_mass_kg);
    m.body.joint_friction_nm = motor.frictionTorque() + r.motor.rolling_resistance *
                                                            weight_per_wheel *
                                                            s.robot.wheel_radius_m;
  }
  return m;
}

RealismLoop::RealismLoop(const RealismDef& d, std::uint64_t seed, const RobotBuild& b,
                         const RobotDef& nominal, const Pose2& start, double dt_s)
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

bool RealismLoop::controlDue(long k) const {
  if (def.control.rate_hz <= 0.0) return true;
  return static_cast<double>(k) * dt >=
         static_cast<double>(next_tick) / def.control.rate_hz - 1e-9 * dt;
}

void RealismLoop::tick(long k, const WheelSpeeds& command) {
  pending.emplace_back(k + latency_steps, command);
  if (def.control.rate_hz <= 0.0) return;
  while (static_cast<double>(next_tick) / def.control.rate_hz - 1e-9 * dt <=
         static_cast<double>(k) * dt) {
    ++next_tick;
  }
}

double RealismLoop::holdPeriod() const {
  return def.control.rate_hz > 0.0 ? 1.0 / def.control.rate_hz : dt;
}

void RealismLoop::actuate(long k, DynamicsWorld& world) {
  while (!pending.empty() && pending.front().first <= k) {
    setpoint = pending.front().second;
    pending.pop_front();
  }
  if (!def.motor.enabled) {
    world.setWheelTargets(setpoint);
    return;
  }
  if (k % wheel_loop_steps == 0) {
    const double period = static_cast<double>(wheel_loop_steps) * dt;
    // Speed from the encoder's count difference over the loop's period; the first tick has no
    // earlier count.
    const WheelSpeeds speed =
        k == 0 ? WheelSpeeds{}
               : WheelSpeeds{(encoder.left_radps - encoder_at_loop.left_radps) / period,
                             (encoder.right_radps - encoder_at_loop.right_radps) / period};
    encoder_at_loop = encoder;
    effort = {left_loop.update(setpoint.left_radps, speed.left_radps, period),
              right_loop.update(setpoint.right_radps, speed.right_radps, period)};
  }
  const WheelSpeeds& omega = world.robot().wheels;
  torque = {left_motor.torque(effort.left_radps, omega.left_radps),
            right_motor.torque(effort.right_radps, omega.right_radps)};
  world.setWheelTorques(torque);
}

void RealismLoop::sense(const DynamicsWorld& world) {
  const long now = world.steps();
  const RobotState& state = world.robot();
  const WheelSpeeds before = encoder;
  encoder = {left_encoder.read(state.wheel_angles.left_radps, encoder_rng),
             right_encoder.read(state.wheel_angles.right_radps, encoder_rng)};
  estimator.predict(now, radius * (encoder.left_radps - before.left_radps),
                    radius * (encoder.right_radps - before.right_radps));
  sensor.observe(now, state.pose, pose_rng);
  for (const PoseMeasurement& m : sensor.deliver(now)) {
    if (estimator.correct(m)) {
      received.push_back(m);
    } else {
      ++dropped_late;
    }
  }
}

}  // namespace parksim
