#pragma once
// Everything between the tracking controller and the physics when the realism is not ideal
// (realism/RealismDef.h): the robot as built (calibration errors and motor gains drawn once
// per episode), the control loop's ticks and latency, the wheel-speed loop and DC motors, the
// encoders, the pose sensor and the estimator. Internal to sim/ (Episode.cpp drives it).
//
// One physics step under a realism: controlDue -> tick (the controller's command, delivered
// after the latency) -> actuate (set-points, wheel-speed loop, motors) -> DynamicsWorld::step
// -> sense (encoders, odometry, pose sensor, the estimator's corrections), in that order.

#include <cstdint>
#include <deque>
#include <random>
#include <utility>
#include <vector>

#include "parksim/core/geometry/Pose2.h"
#include "parksim/core/model/DiffDrive.h"
#include "parksim/core/model/Scenario.h"
#include "parksim/realism/RealismDef.h"
#include "parksim/sim/world/DynamicsWorld.h"

namespace parksim {

/// The robot as built for one episode.
struct RobotBuild {
  double left_scale = 1.0;   ///< true left wheel radius / nominal
  double right_scale = 1.0;  ///< true right wheel radius / nominal
  double track_scale = 1.0;  ///< true track / nominal wheel base
  double left_gain = 1.0;    ///< left motor's gain / nominal
  double right_gain = 1.0;   ///< right motor's gain / nominal
};

/// Draws the robot as built from the realism's calibration and motor ranges; the nominal robot
/// when the realism is not active. Each realism layer draws from its own generator seeded by
/// (noise_seed, layer), so a layer switched off or changed does not shift another's draws.
RobotBuild drawRobotBuild(const RealismDef& realism, std::uint64_t noise_seed);

/// `model` with the robot as built: its true radii and track, and with motors enabled the
/// torque drive with the motor's axle inertia and its drive-train and rolling friction.
/// Unchanged when the realism is not active.
SimModelDef withRobotBuild(SimModelDef model, const RealismDef& realism, const RobotBuild& build,
                           const Scenario& scenario);

struct RealismLoop {
  /// `nominal`: the robot the controller and the odometry believe in; `start`: the estimator's
  /// initial pose (lot frame); `dt_s`: the physics time step.
  RealismLoop(const RealismDef& d, std::uint64_t noise_seed, const RobotBuild& b,
              const RobotDef& nominal, const Pose2& start, double dt_s);

  /// Whether physics step k (from t = k dt) starts with a control tick.
  bool controlDue(long k) const;
  /// The control tick at step k: `command` arrives at step k + the latency.
  void tick(long k, const WheelSpeeds& command);
  /// Before physics step k: the set-points that have arrived, the wheel-speed loop and the
  /// motors' torques (or, without motors, the set-points as motor targets), applied to `world`.
  void actuate(long k, DynamicsWorld& world);
  /// After the physics step: encoders, odometry, the pose sensor and the estimator's
  /// corrections.
  void sense(const DynamicsWorld& world);
  /// How long one command is held: the control period (or one step without a control rate).
  double holdPeriod() const;

  RealismDef def;
  RobotBuild build;
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
};

}  // namespace parksim
