#include "parksim/rl/ParkingTask.h"

#include <algorithm>
#include <cmath>
#include <random>

#include "parksim/collision/BulletCollisionWorld.h"
#include "parksim/core/io/Error.h"
#include "parksim/core/io/NumberFormat.h"
#include "parksim/rl/TaskDrive.h"
#include "parksim/rl/TaskReward.h"

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

// The step at which an episode is truncated: the task's own limit, else the hard one.
long stepLimit(const ParkingTaskDef& def) {
  return def.max_episode_steps > 0 ? def.max_episode_steps : kMaxTaskEpisodeSteps;
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
                  ? makeDynamicDrive(scenario, def, stepLimit(def), steps_per_action)
                  : makeKinematicDrive(scenario, def, *collision)),
        bounds(taskObservationBounds(scenario, period_s)) {}

  Scenario scenario;
  ParkingTaskDef def;
  long steps_per_action;
  double period_s;
  std::unique_ptr<BulletCollisionWorld> collision;  // before drive: the kinematic drive uses it
  std::unique_ptr<TaskDrive> drive;
  TaskObservationBounds bounds;

  TaskSeed seeding;
  Pose2 start;
  std::uint64_t noise_seed = 0;
  long steps = 0;
  bool started = false;
  bool running = false;
  DriveState state;
  TaskStep last;
  double potential = 0.0;  // of the last observed state (rl/TaskReward.h)

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
    last.observation =
        scenario.robot.isCar()
            ? taskCarObservation(state.estimate, state.twist.v_mps, state.steer_rad,
                                 scenario.goal.pose, bounds)
            : taskObservation(state.estimate, state.twist, scenario.goal.pose, bounds);
    TaskInfo& info = last.info;
    info.pose = state.pose;
    info.estimate = state.estimate;
    info.t_s = state.t_s;
    info.speed_mps = state.twist.v_mps;
    info.steer_rad = state.steer_rad;
    info.goal_pos_err_m = positionDistance(state.pose, scenario.goal.pose);
    info.goal_heading_err_rad = goalHeadingError(scenario.goal, state.pose.theta);
    info.is_success =
        taskOutcome(def, scenario.goal, scenario.lot, state.pose, !state.contacts.empty()).success;
    info.contacts = state.contacts;
  }

  double currentPotential() const {
    return taskPotential(def, last.info.goal_pos_err_m, last.info.goal_heading_err_rad);
  }

  const TaskStep& begin(const Pose2& pose, std::uint64_t seed) {
    start = pose;
    noise_seed = seed;
    steps = 0;
    started = true;
    running = false;  // until the drive has the new episode
    drive->reset(start, noise_seed, state);
    observe();
    potential = currentPotential();
    last.reward = 0.0;
    last.terminated = last.truncated = false;
    running = true;
    return last;
  }

  void judge() {
    const TaskInfo& info = last.info;
    const TaskOutcome outcome =
        taskOutcome(def, scenario.goal, scenario.lot, info.pose, !info.contacts.empty());
    const double before = potential;
    potential = currentPotential();
    last.reward = taskReward(def, before, potential, outcome);
    last.terminated = outcome.terminated;
    last.truncated = steps >= stepLimit(def);
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
  checkTaskAction(action);
  d.running = false;  // a drive that throws (a diverged simulation) leaves no usable episode
  d.drive->act(action, d.steps_per_action, d.state);
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
const TaskObservation& ParkingTask::observationLow() const { return impl_->bounds.low; }
const TaskObservation& ParkingTask::observationHigh() const { return impl_->bounds.high; }

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
