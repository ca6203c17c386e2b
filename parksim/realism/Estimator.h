#pragma once
// What the controller believes the robot's pose is.
//   truth     the simulated pose itself (today's idealised loop; Episode reads it directly);
//   odometry  dead reckoning from the wheel encoders with the nominal geometry;
//   fused     an extended Kalman filter: odometry predicts at every physics step, delayed pose
//             measurements correct it at the step they were taken (the state and covariance
//             of every recent step are kept; a late measurement corrects the stored state of
//             its own time, and the steps since are replayed from their stored odometry).

#include <deque>
#include <string>

#include <Eigen/Core>

#include "parksim/core/geometry/Pose2.h"
#include "parksim/core/model/RobotDef.h"
#include "parksim/realism/PoseSensor.h"

namespace parksim {

enum class EstimatorKind { kTruth, kOdometry, kFused };

const char* toString(EstimatorKind kind);
/// Parses truth, odometry or fused; throws Error otherwise.
EstimatorKind estimatorKindFromString(const std::string& name);

struct EstimatorDef {
  EstimatorKind kind = EstimatorKind::kTruth;
  /// Odometry's assumed random error: the variance of a wheel's travel grows by this much per
  /// metre it travels, m (1e-4: 1 cm standard deviation after 1 m).
  double odometry_variance_per_m = 1e-4;
  /// Measurement noise the filter assumes; <= 0: the pose sensor's own standard deviations.
  double assumed_position_noise_m = 0.0;
  double assumed_heading_noise_rad = 0.0;
  /// Steps of history kept for late measurements (older ones are dropped), >= latency.
  long history_steps = 480;
};

class Estimator {
 public:
  /// Starts at `start`, known exactly. `sensor` gives the measurement noise unless the def
  /// overrides it.
  Estimator(const EstimatorDef& def, const RobotDef& nominal, const PoseSensorDef& sensor,
            const Pose2& start);

  /// Odometry of physics step `step`: each wheel's travel since the previous step as the
  /// encoders report it with the nominal radius, m.
  void predict(long step, double left_m, double right_m);
  /// A pose measurement taken at the end of step m.taken_step (fused only; ignored otherwise).
  /// Returns false when it is older than the history.
  bool correct(const PoseMeasurement& m);

  Pose2 pose() const;
  /// Covariance of (x, y, theta) now.
  const Eigen::Matrix3d& covariance() const;

 private:
  struct Entry {
    long step = 0;
    Eigen::Vector3d x;
    Eigen::Matrix3d p;
    double left_m = 0.0;
    double right_m = 0.0;
  };
  void propagate(const Entry& from, Entry& to) const;

  EstimatorDef def_;
  double track_;
  Eigen::Matrix3d r_;
  std::deque<Entry> history_;
};

}  // namespace parksim
