// The kinematic fidelity for a car: highway-env parking-v0's kinematic bicycle, with the car's
// limits. An action commands an acceleration and a steering angle's target (taskCarCommand);
// at every physics step of the control period (the world's physics.time_step_s, the stated
// integration step) the steering angle moves towards its target by at most
// max_steer_rate_radps * dt, the speed changes by accel * dt and is clipped to max_speed_mps,
// and the car then moves along the exact arc of that speed and curvature
// tan(steer) / axle_distance for dt (integrateExact): a constant steering angle drives a circle
// of radius axle_distance / tan(steer) exactly, and the car never turns without moving.
// Collisions are checked as the differential drive's (KinematicDrive.cpp): no footprint point
// moves more than kinematic_check_m between two checks, and the car stops (speed 0) at the last
// free pose before a penetration for the rest of the action; its wheels still steer.

#include <algorithm>
#include <cmath>

#include "parksim/rl/KinematicSweep.h"
#include "parksim/rl/TaskDrive.h"

namespace parksim {

namespace {

class KinematicCarDrive final : public TaskDrive {
 public:
  KinematicCarDrive(const Scenario& scenario, const ParkingTaskDef& def,
                    const BulletCollisionWorld& collision)
      : robot_(scenario.robot),
        dt_(scenario.physics.time_step_s),
        sweep_(scenario, def, collision) {}

  void reset(const Pose2& start, std::uint64_t /*noise_seed*/, DriveState& out) override {
    pose_ = start;
    speed_mps_ = 0.0;
    steer_rad_ = 0.0;  // straight wheels, as a plan starts (docs/cars.md)
    t_s_ = 0.0;
    out.contacts.clear();
    report(Twist{}, out);
  }

  void act(const TaskAction& action, long steps, DriveState& out) override {
    const CarCommand command = taskCarCommand(action, robot_);
    const double max_turn = robot_.max_steer_rate_radps * dt_;
    out.contacts.clear();
    Twist twist;
    for (long i = 0; i < steps; ++i) {
      steer_rad_ += std::clamp(command.steer_rad - steer_rad_, -max_turn, max_turn);
      if (!out.contacts.empty()) continue;  // stopped against an obstacle
      speed_mps_ = std::clamp(speed_mps_ + command.accel_mps2 * dt_, -robot_.max_speed_mps,
                              robot_.max_speed_mps);
      twist = {speed_mps_, speed_mps_ * std::tan(steer_rad_) / robot_.axle_distance_m};
      if (!move(twist, out)) {
        speed_mps_ = 0.0;
        twist = {};
      }
    }
    t_s_ += static_cast<double>(steps) * dt_;
    report(twist, out);
  }

  std::vector<Pose2> obstaclePoses() const override { return sweep_.obstaclePoses(); }

 private:
  // Moves along `twist` for one physics step, checked; false (pose_ the last free pose, the
  // contacts in `out`) on a penetration. Standing still is not checked: the pose is the last
  // one checked.
  bool move(const Twist& twist, DriveState& out) {
    if (twist.v_mps == 0.0) return true;
    pose_ = sweep_.move(pose_, twist, dt_, out.contacts);
    return out.contacts.empty();
  }

  void report(const Twist& twist, DriveState& out) const {
    out.pose = out.estimate = pose_;
    out.twist = twist;
    out.steer_rad = steer_rad_;
    out.t_s = t_s_;
  }

  RobotDef robot_;
  double dt_;
  KinematicSweep sweep_;
  Pose2 pose_;
  double speed_mps_ = 0.0;  // of the reference point, negative in reverse
  double steer_rad_ = 0.0;  // front-wheel angle, left positive
  double t_s_ = 0.0;
};

}  // namespace

std::unique_ptr<TaskDrive> makeKinematicCarDrive(const Scenario& scenario,
                                                 const ParkingTaskDef& def,
                                                 const BulletCollisionWorld& collision) {
  return std::make_unique<KinematicCarDrive>(scenario, def, collision);
}

}  // namespace parksim
