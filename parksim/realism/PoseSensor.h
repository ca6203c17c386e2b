#pragma once
// A pose sensor outside the robot (overhead camera, motion capture): it samples the true pose
// at its rate, adds Gaussian noise, loses a share of samples, and delivers each one `latency_s`
// after it was taken, stamped with the time it was taken (as mocap systems stamp frames).
// Times are whole physics steps: a sample is taken at the first step at or after each multiple
// of the period, and arrives round(latency / dt) steps later.

#include <deque>
#include <random>
#include <vector>

#include "parksim/core/geometry/Pose2.h"

namespace parksim {

struct PoseSensorDef {
  /// Off: no pose measurements (dead reckoning or truth only).
  bool enabled = false;
  double rate_hz = 100.0;             ///< samples per second
  double latency_s = 0.06;            ///< from sampling to delivery, s
  double position_noise_m = 5e-4;     ///< standard deviation of x and y each, m
  double heading_noise_rad = 0.0054;  ///< standard deviation of the heading, rad
  double dropout_probability = 0.0;   ///< share of samples lost, 0..1
};

struct PoseMeasurement {
  long taken_step = 0;    ///< physics step at whose end it was taken
  long arrival_step = 0;  ///< physics step at whose end the controller gets it
  Pose2 pose;             ///< measured pose (with noise), lot frame
};

class PoseSensor {
 public:
  PoseSensor(const PoseSensorDef& def, double dt_s);

  /// Called at the end of every physics step with the true pose: takes a sample when one is
  /// due (dropped ones count as taken).
  void observe(long step, const Pose2& truth, std::mt19937_64& rng);
  /// Measurements that arrive at the end of `step`, oldest first (moved out).
  std::vector<PoseMeasurement> deliver(long step);

  long taken() const { return taken_; }
  long dropped() const { return dropped_; }
  long latencySteps() const { return latency_steps_; }

 private:
  PoseSensorDef def_;
  double dt_;
  long latency_steps_;
  long next_sample_ = 0;  // index of the next sampling instant (multiples of the period)
  long taken_ = 0;
  long dropped_ = 0;
  std::deque<PoseMeasurement> in_flight_;
};

}  // namespace parksim
