// The kinematic fidelity: held wheel speeds move the robot along one exact arc per action
// (integrateExact), checked against the planner's collision checker so densely that no point
// of the footprint moves more than kinematic_check_m between two checks. The robot stops at
// the last free pose before a penetration, as a chassis pressed against a fixed obstacle would.

#include <algorithm>
#include <cmath>
#include <string>
#include <unordered_map>

#include "parksim/collision/BulletCollisionWorld.h"
#include "parksim/core/model/Geometry.h"
#include "parksim/rl/TaskDrive.h"

namespace parksim {

namespace {

class KinematicDrive final : public TaskDrive {
 public:
  KinematicDrive(const Scenario& scenario, const ParkingTaskDef& def,
                 const BulletCollisionWorld& collision)
      : robot_(scenario.robot),
        dt_(scenario.physics.time_step_s),
        check_m_(def.kinematic_check_m),
        radius_m_(footprintRadius(scenario.robot)),
        collision_(collision) {
    for (std::size_t i = 0; i < scenario.obstacles.size(); ++i) {
      const Obstacle& o = scenario.obstacles[i];
      index_.emplace(o.name, static_cast<int>(i));
      obstacles_.push_back({o.box.center.x(), o.box.center.y(), o.box.yaw});
    }
  }

  void reset(const Pose2& start, std::uint64_t /*noise_seed*/, DriveState& out) override {
    pose_ = start;
    t_s_ = 0.0;
    out.contacts.clear();
    out.pose = out.estimate = pose_;
    out.twist = {};
    out.t_s = t_s_;
  }

  void act(const WheelSpeeds& wheels, long steps, DriveState& out) override {
    const double period = static_cast<double>(steps) * dt_;
    const Twist twist = toTwist(wheels, robot_);
    // A footprint point at distance r from the reference point moves at most |v| + |omega| r.
    const double travel =
        (std::abs(twist.v_mps) + std::abs(twist.omega_radps) * radius_m_) * period;
    const long checks = std::max(1L, static_cast<long>(std::ceil(travel / check_m_)));
    out.contacts.clear();
    Pose2 reached = pose_;
    for (long j = 1; j <= checks; ++j) {
      const double t =
          j == checks ? period : period * static_cast<double>(j) / static_cast<double>(checks);
      const Pose2 pose = integrateExact(pose_, twist, t);
      if (!collision_.isFree(pose)) {
        for (const std::string& name : collision_.overlapping(pose)) {
          out.contacts.push_back(index_.at(name));
        }
        std::sort(out.contacts.begin(), out.contacts.end());
        break;
      }
      reached = pose;
    }
    pose_ = reached;
    t_s_ += period;
    out.pose = out.estimate = pose_;
    out.twist = out.contacts.empty() ? twist : Twist{};
    out.t_s = t_s_;
  }

  std::vector<Pose2> obstaclePoses() const override { return obstacles_; }

 private:
  RobotDef robot_;
  double dt_;
  double check_m_;
  double radius_m_;
  const BulletCollisionWorld& collision_;
  std::unordered_map<std::string, int> index_;  // obstacle name -> scenario index
  std::vector<Pose2> obstacles_;
  Pose2 pose_;
  double t_s_ = 0.0;
};

}  // namespace

std::unique_ptr<TaskDrive> makeKinematicDrive(const Scenario& scenario, const ParkingTaskDef& def,
                                              const BulletCollisionWorld& collision) {
  return std::make_unique<KinematicDrive>(scenario, def, collision);
}

}  // namespace parksim
