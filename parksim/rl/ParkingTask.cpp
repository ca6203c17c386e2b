#include "parksim/rl/ParkingTask.h"

#include <algorithm>
#include <cmath>
#include <random>

#include "parksim/collision/BulletCollisionWorld.h"
#include "parksim/core/Error.h"
#include "parksim/core/NumberFormat.h"
#include "parksim/rl/TaskDrive.h"

namespace parksim {

namespace {

// Attempts at a collision-free perturbed start before falling back to the world's start.
constexpr int kStartAttempts = 100;

std::mt19937_64 episodeRng(const TaskSeed& s) {
  std::seed_seq seq{static_cast<std::uint32_t>(s.seed & 0xffffffffU),
                    static_cast<std::uint32_t>(s.seed >> 32U),
                    static_cast<std::uint32_t>(s.episode & 0xffffffffU),
                    static_cast<std::uint32_t>(s.episode >> 32U)};
  return std::mt19937_64(seq);
}

const ParkingTaskDef& validated(const ParkingTaskDef& def, const Scenario& scenario) {
  validateTaskDef(def);
  const double dt = scenario.physics.time_step_s;
  if (!(dt > 0.0 && std::isfinite(dt))) {
    throw Error("parking task: the world's physics.time_step_s must be positive, got " +
                formatGeneral(dt));
  }
  return def;
}

long stepsPerAction(const ParkingTaskDef& def, double dt) {
  return std::max(1L, std::lround(def.control_period_s / dt));
}

}  // namespace

struct ParkingTask::Impl {
  Impl(const Scenario& s, const ParkingTaskDef& d)
      : scenario(s),
        def(validated(d, s)),
        steps_per_action(stepsPerAction(def, s.physics.time_step_s)),
        period_s(static_cast<double>(steps_per_action) * s.physics.time_step_s),
        collision(std::make_unique<BulletCollisionWorld>(scenario)),
        drive(def.fidelity == TaskFidelity::kDynamics
                  ? makeDynamicDrive(scenario, def, def.max_episode_steps, steps_per_action)
                  : makeKinematicDrive(scenario, def, *collision)) {
    const RobotDef& r = scenario.robot;
    const double v_max = r.max_wheel_speed_radps * r.wheel_radius_m;
    const double omega_max = 2.0 * v_max / r.wheel_base_m;
    // The reference point is inside the lot when an action starts (else the episode was
    // truncated), and one action carries it at most v_max * period; doubled for the estimate's
    // error and for pushes. Speeds get half again for overshoot and collisions.
    const double margin = 2.0 * v_max * period_s;
    // The goal's part has the robot's position and heading bounds, not the goal's values:
    // Gymnasium's checker warns of bounds with low == high, and a task may move its goal.
    const LotBounds& lot = scenario.lot;
    const auto x_min = static_cast<float>(lot.x_min_m - margin);
    const auto y_min = static_cast<float>(lot.y_min_m - margin);
    const auto x_max = static_cast<float>(lot.x_max_m + margin);
    const auto y_max = static_cast<float>(lot.y_max_m + margin);
    const auto v = static_cast<float>(1.5 * v_max);
    const auto omega = static_cast<float>(1.5 * omega_max);
    low = {x_min, y_min, -1.0F, -1.0F, -v, -omega, x_min, y_min, -1.0F, -1.0F};
    high = {x_max, y_max, 1.0F, 1.0F, v, omega, x_max, y_max, 1.0F, 1.0F};
  }

  Scenario scenario;
  ParkingTaskDef def;
  long steps_per_action;
  double period_s;
  std::unique_ptr<BulletCollisionWorld> collision;  // before drive: the kinematic drive uses it
  std::unique_ptr<TaskDrive> drive;
  TaskObservation low{};
  TaskObservation high{};

  TaskSeed seeding;
  Pose2 start;
  std::uint64_t noise_seed = 0;
  long steps = 0;
  bool started = false;
  bool running = false;
  DriveState state;
  TaskStep last;

  Pose2 drawStart(std::mt19937_64& rng) const {
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    const Pose2& s = scenario.start;
    for (int attempt = 0; attempt < kStartAttempts; ++attempt) {
      const double dx = unit(rng) * def.start_position_noise_m;
      const double dy = unit(rng) * def.start_position_noise_m;
      const double dtheta = unit(rng) * def.start_heading_noise_rad;
      const Pose2 pose{s.x + dx, s.y + dy, wrapAngle(s.theta + dtheta)};
      if (collision->isFree(pose)) return pose;
    }
    return s;
  }

  void observe() {
    const Pose2& e = state.estimate;
    const Pose2& g = scenario.goal.pose;
    const std::array<double, kTaskObservationSize> values = {
        e.x, e.y, std::cos(e.theta), std::sin(e.theta), state.twist.v_mps, state.twist.omega_radps,
        g.x, g.y, std::cos(g.theta), std::sin(g.theta)};
    for (std::size_t i = 0; i < kTaskObservationSize; ++i) {
      last.observation[i] = std::clamp(static_cast<float>(values[i]), low[i], high[i]);
    }
    TaskInfo& info = last.info;
    info.pose = state.pose;
    info.estimate = state.estimate;
    info.t_s = state.t_s;
    info.goal_pos_err_m = positionDistance(state.pose, scenario.goal.pose);
    info.goal_heading_err_rad = goalHeadingError(scenario.goal, state.pose.theta);
    info.is_success = info.goal_pos_err_m <= def.success_position_m &&
                      info.goal_heading_err_rad <= def.success_heading_rad;
    info.contacts = state.contacts;
  }

  const TaskStep& begin(const Pose2& pose, std::uint64_t seed) {
    start = pose;
    noise_seed = seed;
    steps = 0;
    started = true;
    running = false;  // until the drive has the new episode
    drive->reset(start, noise_seed, state);
    observe();
    last.reward = 0.0;
    last.terminated = last.truncated = false;
    running = true;
    return last;
  }

  void judge() {
    const TaskInfo& info = last.info;
    const bool contact = !info.contacts.empty();
    last.reward = -std::sqrt(info.goal_pos_err_m / def.distance_scale_m +
                             def.heading_weight * info.goal_heading_err_rad / kPi);
    if (contact) last.reward += def.contact_reward;
    if (info.is_success) last.reward += def.success_reward;
    last.terminated = info.is_success || (contact && def.terminate_on_contact);
    const bool outside = !scenario.lot.contains(info.pose.x, info.pose.y);
    last.truncated = !last.terminated && (steps >= def.max_episode_steps || outside);
    running = !(last.terminated || last.truncated);
  }
};

ParkingTask::ParkingTask(const Scenario& scenario, const ParkingTaskDef& def)
    : impl_(std::make_unique<Impl>(scenario, def)) {}

ParkingTask::~ParkingTask() = default;
ParkingTask::ParkingTask(ParkingTask&&) noexcept = default;
ParkingTask& ParkingTask::operator=(ParkingTask&&) noexcept = default;

void ParkingTask::seed(std::uint64_t seed) { impl_->seeding = {seed, 0}; }

TaskSeed ParkingTask::seedState() const { return impl_->seeding; }

void ParkingTask::setSeedState(const TaskSeed& state) { impl_->seeding = state; }

const TaskStep& ParkingTask::reset() {
  Impl& d = *impl_;
  std::mt19937_64 rng = episodeRng(d.seeding);
  ++d.seeding.episode;
  // The noise seed first: how many draws the start takes does not move it.
  const std::uint64_t noise_seed = rng();
  const Pose2 start = d.drawStart(rng);
  return d.begin(start, noise_seed);
}

const TaskStep& ParkingTask::resetAt(const Pose2& start, std::uint64_t noise_seed) {
  if (!std::isfinite(start.x) || !std::isfinite(start.y) || !std::isfinite(start.theta)) {
    throw Error("parking task: the start pose must be finite, got (" + formatGeneral(start.x) +
                ", " + formatGeneral(start.y) + ", " + formatGeneral(start.theta) + ")");
  }
  return impl_->begin(start, noise_seed);
}

const TaskStep& ParkingTask::step(const TaskAction& action) {
  Impl& d = *impl_;
  if (!d.running) {
    throw Error(d.started ? "parking task: the episode has ended (terminated or truncated); "
                            "reset to start the next one"
                          : "parking task: no episode yet; reset first");
  }
  if (!std::isfinite(action.left) || !std::isfinite(action.right)) {
    throw Error("action: wheel speed fractions must be finite numbers, got (" +
                formatGeneral(action.left) + ", " + formatGeneral(action.right) + ")");
  }
  const double max = d.scenario.robot.max_wheel_speed_radps;
  const WheelSpeeds wheels{std::clamp(action.left, -1.0, 1.0) * max,
                           std::clamp(action.right, -1.0, 1.0) * max};
  d.running = false;  // a drive that throws (a diverged simulation) leaves no usable episode
  d.drive->act(wheels, d.steps_per_action, d.state);
  ++d.steps;
  d.observe();
  d.judge();
  return d.last;
}

bool ParkingTask::running() const { return impl_->running; }
long ParkingTask::steps() const { return impl_->steps; }
const TaskStep& ParkingTask::last() const { return impl_->last; }
Pose2 ParkingTask::episodeStart() const { return impl_->start; }
std::uint64_t ParkingTask::episodeNoiseSeed() const { return impl_->noise_seed; }
double ParkingTask::controlPeriod() const { return impl_->period_s; }
const TaskObservation& ParkingTask::observationLow() const { return impl_->low; }
const TaskObservation& ParkingTask::observationHigh() const { return impl_->high; }

std::vector<Pose2> ParkingTask::obstaclePoses() const {
  if (!impl_->started) {
    std::vector<Pose2> poses;
    for (const Obstacle& o : impl_->scenario.obstacles) {
      poses.push_back({o.box.center.x(), o.box.center.y(), o.box.yaw});
    }
    return poses;
  }
  return impl_->drive->obstaclePoses();
}

const Scenario& ParkingTask::scenario() const { return impl_->scenario; }
const ParkingTaskDef& ParkingTask::def() const { return impl_->def; }

}  // namespace parksim
