// The kinematic fidelity: held wheel speeds move the robot along one exact arc per action
// (integrateExact), checked against the planner's collision checker so densely that no point
// of the footprint moves more than kinematic_check_m between two checks. The robot stops at
// the last free pose before a penetration, as a chassis pressed against a fixed obstacle would.

#include "parksim/rl/KinematicSweep.h"
#include "parksim/rl/TaskDrive.h"

namespace parksim {

namespace {

class KinematicDrive final : public TaskDrive {
 public:
  KinematicDrive(const Scenario& scenario, const ParkingTaskDef& def,
                 const BulletCollisionWorld& collision)
      : robot_(scenario.robot),
        dt_(scenario.physics.time_step_s),
        sweep_(scenario, def, collision) {}

  void reset(const Pose2& start, std::uint64_t /*noise_seed*/, DriveState& out) override {
    pose_ = start;
    t_s_ = 0.0;
    out.contacts.clear();
    out.pose = out.estimate = pose_;
    out.twist = {};
    out.t_s = t_s_;
  }

  void act(const TaskAction& action, long steps, DriveState& out) override {
    const double period = static_cast<double>(steps) * dt_;
    const Twist twist = toTwist(taskWheelSpeeds(action, robot_), robot_);
    out.contacts.clear();
    const Pose2 reached = sweep_.move(pose_, twist, period, out.contacts);
    pose_ = reached;
    t_s_ += period;
    out.pose = out.estimate = pose_;
    out.twist = out.contacts.empty() ? twist : Twist{};
    out.t_s = t_s_;
  }

  std::vector<Pose2> obstaclePoses() const override { return sweep_.obstaclePoses(); }

 private:
  RobotDef robot_;
  double dt_;
  KinematicSweep sweep_;
  Pose2 pose_;
  double t_s_ = 0.0;
};

}  // namespace

std::unique_ptr<TaskDrive> makeKinematicDrive(const Scenario& scenario, const ParkingTaskDef& def,
                                              const BulletCollisionWorld& collision) {
  if (scenario.robot.isCar()) return makeKinematicCarDrive(scenario, def, collision);
  return std::make_unique<KinematicDrive>(scenario, def, collision);
}

}  // namespace parksim
