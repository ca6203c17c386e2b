// The dynamics fidelity: the task's actions are wheel commands held through Episode's step API
// (sim/episode/Episode.h), so the robot is the one `parksim run` drives, realism included, and the
// controller's view is the Episode's estimate. A car's action is a CarCommand (taskCarCommand:
// acceleration and steering target, as the kinematic car's) given to Episode::step at every
// physics step: the Episode ramps its commanded speed by accel * dt a step (by accel * the
// control loop's period at a realism's ticks) within max_speed_mps, and the car's steering
// servos turn its front wheels toward the target at max_steer_rate (sim/CarBody.h). The Episode's
// plan is the start pose held still for longer than the task can last: its tracking measurements
// mean nothing here, and its end is never reached.

#include <algorithm>
#include <climits>
#include <cmath>

#include "parksim/rl/TaskDrive.h"
#include "parksim/sim/episode/Episode.h"

namespace parksim {

namespace {

class DynamicDrive final : public TaskDrive {
 public:
  DynamicDrive(const Scenario& scenario, const ParkingTaskDef& def, long max_actions, long steps)
      : scenario_(scenario), model_(def.model), touched_(scenario.obstacles.size(), 0) {
    const double dt = scenario.physics.time_step_s;
    const double physics_steps = static_cast<double>(max_actions + 1) * static_cast<double>(steps);
    duration_s_ = physics_steps * dt;
    execution_.realism = def.realism;
    // Only the first and the last row are kept: the task reads the current instant.
    execution_.csv_stride_steps = INT_MAX;
    // The task's own step limit governs; the Episode's must not end it first.
    execution_.max_steps = physics_steps + std::ceil(execution_.max_stop_time_s / dt) + 2.0;
    // The robot may roam the whole lot (the Episode would size the ground to its plan).
    if (!model_.has_reach) {
      model_.has_reach = true;
      model_.reach = scenario.lot;
    }
  }

  void reset(const Pose2& start, std::uint64_t noise_seed, DriveState& out) override {
    Trajectory plan;
    plan.points = {{0.0, start, {}}, {duration_s_, start, {}}};
    ExecutionDef execution = execution_;
    execution.noise_seed = noise_seed;
    episode_.reset();  // one Bullet world at a time
    episode_ = std::make_unique<Episode>(scenario_, plan, execution, model_);
    encoders_ = {};
    out.contacts.clear();
    observe(0.0, out);
  }

  void act(const TaskAction& action, long steps, DriveState& out) override {
    const bool car = scenario_.robot.isCar();
    const WheelSpeeds wheels = car ? WheelSpeeds{} : taskWheelSpeeds(action, scenario_.robot);
    const CarCommand command = car ? taskCarCommand(action, scenario_.robot) : CarCommand{};
    out.contacts.clear();
    for (long i = 0; i < steps; ++i) {
      if (car) {
        episode_->step(command);
      } else {
        episode_->step(wheels);
      }
      for (int index : episode_->world().chassisContacts()) {
        char& seen = touched_[static_cast<std::size_t>(index)];
        if (seen == 0) out.contacts.push_back(index);
        seen = 1;
      }
    }
    for (int index : out.contacts) touched_[static_cast<std::size_t>(index)] = 0;
    std::sort(out.contacts.begin(), out.contacts.end());
    observe(static_cast<double>(steps) * episode_->world().timeStep(), out);
  }

  std::vector<Pose2> obstaclePoses() const override { return episode_->world().obstaclePoses(); }

 private:
  // The ideal robot's controller reads the true state; under a realism it reads the estimate
  // and the encoders (their mean speed over the action: what firmware can tell).
  void observe(double elapsed_s, DriveState& out) {
    const DynamicsWorld& world = episode_->world();
    const RobotState& robot = world.robot();
    out.pose = robot.pose;
    out.t_s = world.time();
    out.steer_rad = robot.steer_rad;
    if (!execution_.realism.active()) {
      out.estimate = robot.pose;
      out.twist = robot.twist;
      return;
    }
    const ExecutedRow& row = episode_->current();
    out.estimate = row.estimate;
    out.steer_rad = row.steer_rad;  // measured
    out.twist = {};
    if (elapsed_s > 0.0) {
      const WheelSpeeds mean{(row.encoder_rad.left_radps - encoders_.left_radps) / elapsed_s,
                             (row.encoder_rad.right_radps - encoders_.right_radps) / elapsed_s};
      out.twist = toTwist(mean, scenario_.robot);
    }
    encoders_ = row.encoder_rad;
  }

  Scenario scenario_;
  ExecutionDef execution_;
  SimModelDef model_;
  double duration_s_ = 0.0;
  std::unique_ptr<Episode> episode_;
  WheelSpeeds encoders_;       // wheel angles the encoders reported at the last observation, rad
  std::vector<char> touched_;  // per obstacle: penetrated during the current action
};

}  // namespace

std::unique_ptr<TaskDrive> makeDynamicDrive(const Scenario& scenario, const ParkingTaskDef& def,
                                            long max_actions, long steps) {
  return std::make_unique<DynamicDrive>(scenario, def, max_actions, steps);
}

}  // namespace parksim
