// The realism layers against predictions from physics: the motor's time constant, where a
// driven wheel must slip (friction and load transfer), odometry with calibration errors, and
// how a delayed pose sensor limits the fused estimate. No number here was copied from a run.

#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "parksim/core/geometry/Angle.h"
#include "parksim/core/io/Error.h"
#include "parksim/core/model/DiffDrive.h"
#include "parksim/realism/Encoder.h"
#include "parksim/realism/Estimator.h"
#include "parksim/realism/MotorModel.h"
#include "parksim/realism/PoseSensor.h"
#include "parksim/realism/RealismDef.h"
#include "parksim/realism/WheelSpeedLoop.h"
#include "parksim/sim/episode/Episode.h"
#include "parksim/sim/world/DynamicsWorld.h"
#include "tests/sim/SimTestSupport.h"

namespace parksim {
namespace {

using testing::emptyLot;
using testing::planFromSegments;
using testing::rampedSegments;

// Mass the wheels carry in a straight line: everything but nothing (the slider has no friction).
double robotMass(const Scenario& s, const SimModelDef& m) {
  return s.physics.chassis_mass_kg + 2.0 * s.physics.wheel_mass_kg + m.support_mass_kg;
}

TEST(MotorModel, UnloadedStepResponseReaches63PercentAtTheTimeConstant) {
  const MotorDef def = presetRealism("lab").motor;
  const MotorModel motor(def, 1.0);
  const double j = motor.axleInertia();
  const double effort = 0.3;
  const double final_speed = effort * def.no_load_speed_radps;
  // J domega/dt = torque(effort, omega), integrated finely (midpoint rule).
  const double dt = 1e-5;
  double omega = 0.0;
  double t = 0.0;
  while (omega < (1.0 - std::exp(-1.0)) * final_speed) {
    const double half = omega + 0.5 * dt * motor.torque(effort, omega) / j;
    omega += dt * motor.torque(effort, half) / j;
    t += dt;
  }
  EXPECT_NEAR(t, def.time_constant_s, 1e-3 * def.time_constant_s);
  // Saturation: effort beyond the supply limit gives the limit's torque.
  EXPECT_DOUBLE_EQ(motor.torque(5.0, 0.0), def.stall_torque_nm * def.supply_limit);
}

TEST(MotorModel, OnTheRobotTheLoadAddsItsInertiaToTheTimeConstant) {
  const Scenario s = emptyLot({0.3, 1.0, 0.0});
  const MotorDef def = presetRealism("lab").motor;
  const MotorModel motor(def, 1.0);
  SimModelDef model;
  model.body.drive = WheelDrive::kTorque;
  model.body.wheel_axle_inertia_kgm2 = motor.axleInertia();
  DynamicsWorld world(s, s.start, model);
  // Each wheel drives half of the robot's mass through its radius: J_eff = J + (M/2) r^2.
  const double r = s.robot.wheel_radius_m;
  const double j_eff = motor.axleInertia() + 0.5 * robotMass(s, model) * r * r;
  const double tau = j_eff * def.no_load_speed_radps / def.stall_torque_nm;
  const double effort = 0.2;  // the start-up torque stays below what friction transmits
  const double final_speed = effort * def.no_load_speed_radps;
  double crossed = -1.0;
  while (world.time() < 5.0 * tau && crossed < 0.0) {
    const WheelSpeeds w = world.robot().wheels;
    world.setWheelTorques(
        {motor.torque(effort, w.left_radps), motor.torque(effort, w.right_radps)});
    world.step();
    if (world.robot().wheels.left_radps >= (1.0 - std::exp(-1.0)) * final_speed) {
      crossed = world.time();
    }
  }
  std::printf("predicted tau %.4f s, 63 %% reached at %.4f s\n", tau, crossed);
  // One step of resolution, plus the torque computed from the previous step's speed.
  EXPECT_NEAR(crossed, tau, 0.05 * tau);
  EXPECT_LT(std::abs(world.robot().slip_mps.left_radps), 1e-3);
}

// Torque at which a wheel starts to slip when both drive the robot forward from rest: the
// friction force mu N per wheel, with the wheels' load N reduced by the load transfer to the
// rear slider (centre of mass height h, slider L behind the axle), and the torque that spins
// the wheel itself up.
double slipTorque(const Scenario& s, const SimModelDef& m) {
  const PhysicsDef& p = s.physics;
  const RobotDef& robot = s.robot;
  const double mass = robotMass(s, m);
  const double chassis_dx = -robot.footprintCenterOffset();  // chassis centre behind the axle
  const double slider = robot.length_m - robot.front_overhang_m - m.support_inset_m;
  const double com_behind = (p.chassis_mass_kg * chassis_dx + m.support_mass_kg * slider) / mass;
  const double chassis_z = 0.5 * (robot.ground_clearance_m + robot.height_m);
  const double h = (p.chassis_mass_kg * chassis_z + 2.0 * p.wheel_mass_kg * robot.wheel_radius_m +
                    m.support_mass_kg * m.support_radius_m) /
                   mass;
  const double mu = p.wheel_friction * p.ground_friction;
  // Both wheels: F = mu (M g (L - c) / L - F h / L)  ->  F = mu M g (L - c) / (L + mu h).
  const double force_total = mu * mass * p.gravity_mps2 * (slider - com_behind) / (slider + mu * h);
  const double f = 0.5 * force_total;
  const double r = robot.wheel_radius_m;
  const double j = 0.4 * p.wheel_mass_kg * r * r;  // sphere about its axle
  // J alpha = tau - F r, alpha = a / r, a = 2 F / M.
  return f * (r + 2.0 * j / (mass * r));
}

double slipAfter(double torque_nm, double seconds) {
  const Scenario s = emptyLot({0.3, 1.0, 0.0});
  SimModelDef model;
  model.body.drive = WheelDrive::kTorque;
  DynamicsWorld world(s, s.start, model);
  double worst = 0.0;
  while (world.time() < seconds) {
    world.setWheelTorques({torque_nm, torque_nm});
    world.step();
    if (world.time() > 0.05) worst = std::max(worst, std::abs(world.robot().slip_mps.left_radps));
  }
  return worst;
}

TEST(WheelSlip, DrivenWheelsSlipOnlyAboveTheTorqueFrictionTransmits) {
  const Scenario s = emptyLot();
  const double limit = slipTorque(s, SimModelDef{});
  const double below = slipAfter(0.8 * limit, 0.25);
  const double above = slipAfter(1.25 * limit, 0.25);
  std::printf("slip torque %.5f N m: slip %.5f m/s at 0.8x, %.5f m/s at 1.25x\n", limit, below,
              above);
  EXPECT_LT(below, 2e-3);
  EXPECT_GT(above, 2e-2);
}

// A plan that turns in place, or drives straight, with the robot's acceleration ramps.
RealismDef calibrationOnly(double left_pct, double right_pct, double track_pct) {
  RealismDef r;
  r.name = "test";
  r.calibration.left_radius_error_pct = left_pct;
  r.calibration.right_radius_error_pct = right_pct;
  r.calibration.track_error_pct = track_pct;
  r.estimator.kind = EstimatorKind::kOdometry;
  return r;
}

// Heading error of odometry at the end of a plan that turns in place by about 360 degrees,
// driven closed loop on odometry (so the estimate follows the plan), true track `track_pct`
// longer than nominal.
double turnHeadingError(double track_pct, double* planned_turn) {
  const Scenario s = emptyLot({1.0, 1.0, 0.0});
  const double w = 4.0;
  const double yaw_rate = 2.0 * w * s.robot.wheel_radius_m / s.robot.wheel_base_m;
  const auto turnOf = [&](const std::vector<testing::Segment>& segs) {
    double turned = 0.0;
    for (const auto& seg : segs) {
      turned += toTwist(seg.wheels, s.robot).omega_radps * seg.duration_s;
    }
    return turned;
  };
  const double ramps = turnOf(rampedSegments({-w, w}, 0.0, s.robot));
  const double hold = std::round((2.0 * kPi - ramps) / yaw_rate / 0.1) * 0.1;
  const std::vector<testing::Segment> segs = rampedSegments({-w, w}, hold, s.robot);
  *planned_turn = turnOf(segs);
  const Trajectory plan = planFromSegments(s.start, segs, s.robot);
  ExecutionDef exec;
  exec.realism = calibrationOnly(0.0, 0.0, track_pct);
  return runEpisode(s, plan, exec).rows.back().est_heading_err_rad;
}

TEST(Odometry, OnePercentTrackErrorGivesAboutThreePointSixDegreesPerTurn) {
  double turn = 0.0;
  const double err = radToDeg(turnHeadingError(1.0, &turn));
  // Odometry turns by (wheel travel difference) / nominal track, the robot by the same over
  // the true track, 1 % longer: the estimate leads by 1 - 1/1.01 of the turn (3.56 deg per
  // revolution). The calibrated robot's own error (slip in the ramps) is measured apart.
  const double predicted = radToDeg(turn * (1.0 - 1.0 / 1.01));
  const double calibrated = radToDeg(turnHeadingError(0.0, &turn));
  std::printf(
      "turned %.1f deg: odometry heading error %.3f deg (%.3f deg calibrated), predicted "
      "%.3f deg\n",
      radToDeg(turn), err, calibrated, predicted);
  EXPECT_NEAR(radToDeg(turn), 360.0, 6.0);
  EXPECT_NEAR(err - calibrated, predicted, 0.2 * predicted);
  EXPECT_NEAR(err, 3.6, 0.2 * 3.6);
}

TEST(Odometry, OnePercentRadiusMismatchCurvesAStraightDriveAsPredicted) {
  const Scenario s = emptyLot({0.2, 0.5, 0.0});
  const double w = 5.0;  // 0.1 m/s: about 1 m in 10 s
  const Trajectory plan = planFromSegments(s.start, rampedSegments({w, w}, 9.5, s.robot), s.robot);
  ExecutionDef exec;
  exec.tracking = TrackingMode::kOpen;  // the wheels turn as planned, the robot curves
  exec.realism = calibrationOnly(0.0, 1.0, 0.0);
  const EpisodeResult result = runEpisode(s, plan, exec);
  const ExecutedRow& last = result.rows.back();
  const double r = s.robot.wheel_radius_m;
  const double left = r * last.encoder_rad.left_radps;           // true travel of the left rim
  const double right = 1.01 * r * last.encoder_rad.right_radps;  // the right wheel is 1 % larger
  const double turn = (right - left) / s.robot.wheel_base_m;
  const double distance = 0.5 * (left + right);
  const double heading = angleDiff(last.pose.theta, s.start.theta);
  std::printf("%.3f m: heading %.4f rad, predicted %.4f rad (curvature %.4f 1/m); odometry %.5f\n",
              distance, heading, turn, turn / distance, last.estimate.theta);
  EXPECT_GT(distance, 0.9);
  EXPECT_NEAR(heading, turn, 0.05 * turn);
  // Odometry believes it drove straight.
  EXPECT_NEAR(angleDiff(last.estimate.theta, s.start.theta), 0.0, 0.05 * turn);
  // The arc's chord ends 1 - cos(turn) / turn ... : lateral offset ~ distance * turn / 2.
  const double lateral = last.pose.y - s.start.y;
  EXPECT_NEAR(lateral, 0.5 * distance * turn, 0.1 * 0.5 * distance * turn);
}

// Kinematic steady turn; odometry 2 % long on both wheels; noise-free pose sensor at 100 Hz
// with latency L. The filter corrects the stored state of each sample's own time and replays
// odometry since, so the estimate's error is the odometry error over the latency plus the age
// of the last sample: 2 % x v x (L + T/2) on average, growing with L, not v x L.
double fusedError(double latency_s) {
  const double dt = 1.0 / 240.0;
  RobotDef robot;
  const double v = 0.1;
  const double omega = 0.5;
  PoseSensorDef sensor;
  sensor.enabled = true;
  sensor.rate_hz = 100.0;
  sensor.latency_s = latency_s;
  sensor.position_noise_m = 0.0;
  sensor.heading_noise_rad = 0.0;
  EstimatorDef est;
  est.kind = EstimatorKind::kFused;
  est.assumed_position_noise_m = 1e-6;
  est.assumed_heading_noise_rad = 1e-6;
  Pose2 truth{0.0, 0.0, 0.0};
  Estimator estimator(est, robot, sensor, truth);
  PoseSensor pose_sensor(sensor, dt);
  std::mt19937_64 rng(1);
  const double left = (v - 0.5 * omega * robot.wheel_base_m) * dt;
  const double right = (v + 0.5 * omega * robot.wheel_base_m) * dt;
  double sum = 0.0;
  long n = 0;
  for (long k = 1; k <= 2400; ++k) {
    truth = integrateExact(truth, {v, omega}, dt);
    estimator.predict(k, 1.02 * left, 1.02 * right);
    pose_sensor.observe(k, truth, rng);
    for (const PoseMeasurement& m : pose_sensor.deliver(k)) estimator.correct(m);
    if (k > 1200) {
      sum += positionDistance(estimator.pose(), truth);
      ++n;
    }
  }
  return sum / static_cast<double>(n);
}

TEST(FusedEstimator, ErrorOnASteadyTurnGrowsWithTheLatencyAsPredicted) {
  const double v = 0.1;
  const double period = 0.01;
  for (double latency : {0.05, 0.1, 0.2}) {
    const double predicted = 0.02 * v * (latency + 0.5 * period);
    const double measured = fusedError(latency);
    std::printf("latency %.2f s: mean error %.4f mm, predicted %.4f mm (v L = %.1f mm)\n", latency,
                measured * 1e3, predicted * 1e3, v * latency * 1e3);
    EXPECT_NEAR(measured, predicted, 0.1 * predicted);
  }
}

TEST(Encoder, QuantisesToWholeCountsAndReportsTheAngleOfTheCount) {
  EncoderDef def;
  def.counts_per_turn = 1000.0;
  Encoder enc(def);
  std::mt19937_64 rng(1);
  const double count = 2.0 * kPi / 1000.0;
  EXPECT_DOUBLE_EQ(enc.read(10.5 * count, rng), 10.0 * count);
  EXPECT_EQ(enc.count(), 10);
  EXPECT_DOUBLE_EQ(enc.read(-0.5 * count, rng), -1.0 * count);
}

TEST(WheelSpeedLoop, IntegratorRemovesAConstantLoadAndDoesNotWindUpInSaturation) {
  WheelSpeedLoopDef def;
  const double no_load = 47.1;
  WheelSpeedLoop loop(def, no_load, 1.0);
  // A wheel held still (stalled) for 8 s: the effort rises to the limit and the integrator
  // stops there (unclamped it would hold 0.6 x 10 x 8 = 48).
  for (int i = 0; i < 1000; ++i) loop.update(10.0, 0.0, 1.0 / 120.0);
  EXPECT_GT(loop.effort(), 0.95);
  EXPECT_LE(loop.effort(), 1.0);
  // Released at the set-point, the effort is the feed-forward plus at most what brought it to
  // the limit (no wind-up): below 10 / 47.1 + (1 - 10 / 47.1 - 0.06 x 10) = 0.4.
  const double e = loop.update(10.0, 10.0, 1.0 / 120.0);
  EXPECT_LT(e, 0.4 + 1e-9);
  // A constant load: the integrator supplies it, and the error goes to zero.
  WheelSpeedLoop loaded(def, no_load, 1.0);
  double omega = 0.0;
  const double j = 1.5e-4;
  const double stall = 0.098;
  for (int i = 0; i < 1200; ++i) {  // 10 s at 120 Hz, wheel integrated within each tick
    const double u = loaded.update(5.0, omega, 1.0 / 120.0);
    for (int k = 0; k < 10; ++k) {
      omega += (1.0 / 1200.0) * (stall * (u - omega / no_load) - 0.01) / j;
    }
  }
  EXPECT_NEAR(omega, 5.0, 1e-3);
}

TEST(Realism, PresetsAreValidAndOnlyIdealIsInactive) {
  for (const std::string& name : realismPresetNames()) {
    const RealismDef r = presetRealism(name);
    EXPECT_NO_THROW(validateRealism(r)) << name;
    EXPECT_EQ(r.active(), name != "ideal") << name;
  }
  EXPECT_THROW(presetRealism("lab2"), Error);
  RealismDef bad = presetRealism("lab");
  bad.pose_sensor.enabled = false;  // fused without a pose sensor
  EXPECT_THROW(validateRealism(bad), Error);
}

}  // namespace
}  // namespace parksim
