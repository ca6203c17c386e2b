#include "parksim/sim/Episode.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "parksim/core/Angle.h"
#include "parksim/core/Error.h"
#include "parksim/sim/ReferenceTrajectory.h"
#include "parksim/sim/TrackingController.h"

namespace parksim {

namespace {

// Step counts from durations: a duration that is a whole number of steps up to rounding counts
// as that number, not one more.
long stepsFor(double duration_s, double dt_s) {
  return static_cast<long>(std::ceil(duration_s / dt_s - 1e-9));
}

double goalHeadingError(const GoalRegion& goal, double theta) {
  double err = std::abs(angleDiff(theta, goal.pose.theta));
  if (goal.either_heading) err = std::min(err, std::abs(angleDiff(theta, goal.pose.theta + kPi)));
  return err;
}

const ExecutionDef& validated(const Scenario& scenario, const Trajectory& plan,
                              const ExecutionDef& def) {
  auto fail = [](const char* what) { throw Error(std::string("execution: ") + what); };
  if (!(def.rest_speed_mps > 0.0)) fail("rest_speed_mps must be positive");
  if (!(def.rest_yaw_rate_radps > 0.0)) fail("rest_yaw_rate_radps must be positive");
  if (!(def.rest_hold_s >= 0.0)) fail("rest_hold_s must not be negative");
  if (!(def.max_stop_time_s >= 0.0)) fail("max_stop_time_s must not be negative");
  if (!(def.contact_merge_s >= 0.0)) fail("contact_merge_s must not be negative");
  if (def.csv_stride_steps < 1) fail("csv_stride_steps must be at least 1");
  checkEpisodeLimits(scenario, plan, def);
  return def;
}

}  // namespace

double checkEpisodeLimits(const Scenario& scenario, const Trajectory& plan,
                          const ExecutionDef& def) {
  if (plan.empty()) throw Error("execution: the plan is empty");
  const double dt = scenario.physics.time_step_s;
  const double duration = plan.duration();
  if (!(dt > 0.0) || !std::isfinite(dt))
    throw Error("execution: physics.time_step_s must be positive");
  if (!std::isfinite(plan.points.front().t_s) || !std::isfinite(duration) || duration < 0.0) {
    throw Error("execution: the plan's times must be finite and increasing");
  }
  // In double, so no duration or step reaches an out-of-range conversion to an integer.
  const double steps = std::ceil((duration + def.max_stop_time_s) / dt - 1e-9);
  if (!(steps <= def.max_steps)) {
    char text[320];
    std::snprintf(text, sizeof text,
                  "execution: the episode needs %.4g physics steps (plan %.6g s + stop %.6g s at "
                  "physics.time_step_s %.6g s), more than the limit of %.4g (docs/limits.md)",
                  steps, duration, def.max_stop_time_s, dt, def.max_steps);
    throw Error(text);
  }
  return steps;
}

struct Episode::Impl {
  Impl(const Scenario& s, const Trajectory& plan, const ExecutionDef& d, const SimModelDef& m)
      : scenario(s),
        def(validated(s, plan, d)),
        reference(plan, s.robot),
        world(s, plan.points.front().pose, m),
        dt(world.timeStep()),
        t0(reference.startTime()),
        plan_steps(stepsFor(reference.endTime() - reference.startTime(), dt)),
        limit_steps(plan_steps + stepsFor(d.max_stop_time_s, dt)),
        rest_steps(std::max(1L, stepsFor(d.rest_hold_s, dt))),
        merge_steps(stepsFor(d.contact_merge_s, dt)),
        last_contact_step(s.obstacles.size(), -1) {
    initial_obstacles = world.obstaclePoses();
    for (std::size_t i = 0; i < s.obstacles.size(); ++i) {
      if (s.obstacles[i].kind == ObstacleKind::kParkedRobot) {
        parked_index.push_back(static_cast<int>(i));
        parked.push_back({s.obstacles[i].name, 0.0, 0.0});
      }
    }
    measure(WheelSpeeds{});
  }

  Scenario scenario;
  ExecutionDef def;
  ReferenceTrajectory reference;
  DynamicsWorld world;
  double dt;
  double t0;
  long plan_steps;
  long limit_steps;
  long rest_steps;
  long merge_steps;

  std::vector<Pose2> initial_obstacles;
  std::vector<int> parked_index;
  std::vector<ParkedRobotDisplacement> parked;

  std::vector<ExecutedRow> rows;
  ExecutedRow current;
  std::vector<long> last_contact_step;  // per obstacle; -1: never touched
  std::vector<ContactEvent> contact_events;
  double sum_sq_pos = 0.0;
  double sum_sq_heading = 0.0;
  double max_pos = 0.0;
  double max_heading = 0.0;
  long measured = 0;
  long steps_at_rest = 0;
  bool finished = false;
  bool at_rest = false;
  std::chrono::steady_clock::duration wall{};

  double planTime(long step) const { return t0 + static_cast<double>(step) * dt; }

  void measure(const WheelSpeeds& command) {
    const long k = world.steps();
    const RobotState& state = world.robot();
    ExecutedRow row;
    row.t_s = static_cast<double>(k) * dt;
    row.pose = state.pose;
    row.reference = reference.poseAt(planTime(k));
    row.wheels_cmd = command;
    row.wheels = state.wheels;
    row.pos_err_m = positionDistance(row.pose, row.reference);
    row.heading_err_rad = angleDiff(row.pose.theta, row.reference.theta);
    current = row;

    max_pos = std::max(max_pos, row.pos_err_m);
    max_heading = std::max(max_heading, std::abs(row.heading_err_rad));
    sum_sq_pos += row.pos_err_m * row.pos_err_m;
    sum_sq_heading += row.heading_err_rad * row.heading_err_rad;
    ++measured;

    for (int index : world.chassisContacts()) {
      long& last = last_contact_step[static_cast<std::size_t>(index)];
      if (last < 0 || k - last > merge_steps) {
        contact_events.push_back(
            {row.t_s, index, scenario.obstacles[static_cast<std::size_t>(index)].name});
      }
      last = k;
    }

    // Positions only, of the parked robots only: no allocation and no heading per step.
    for (std::size_t j = 0; j < parked_index.size(); ++j) {
      const auto i = static_cast<std::size_t>(parked_index[j]);
      const Eigen::Vector2d p = world.obstaclePosition(i);
      const double d = positionDistance({p.x(), p.y(), 0.0}, initial_obstacles[i]);
      parked[j].final_m = d;
      parked[j].max_m = std::max(parked[j].max_m, d);
    }

    if (k >= plan_steps) {
      const bool resting = std::abs(state.twist.v_mps) < def.rest_speed_mps &&
                           std::abs(state.twist.omega_radps) < def.rest_yaw_rate_radps;
      steps_at_rest = resting ? steps_at_rest + 1 : 0;
      if (steps_at_rest >= rest_steps) {
        finished = true;
        at_rest = true;
      }
    }
    if (k >= limit_steps) finished = true;
    if (k % def.csv_stride_steps == 0 || finished) rows.push_back(row);
  }

  WheelSpeeds command() const {
    const long k = world.steps();
    // Wheel speeds are held per control period; the step's midpoint picks the period without
    // depending on how k * dt rounds at a period boundary.
    const double mid = planTime(k) + 0.5 * dt;
    if (def.tracking == TrackingMode::kOpen) return reference.wheelsAt(mid);
    return trackingCommand(world.robot().pose, reference.poseAt(planTime(k)),
                           reference.twistAt(mid), def.gains, scenario.robot);
  }
};

Episode::Episode(const Scenario& scenario, const Trajectory& plan, const ExecutionDef& def,
                 const SimModelDef& model) {
  if (plan.points.empty()) throw Error("simulation: the plan has no points");
  impl_ = std::make_unique<Impl>(scenario, plan, def, model);
}

Episode::~Episode() = default;

void Episode::step() {
  Impl& d = *impl_;
  if (d.finished) return;
  const auto start = std::chrono::steady_clock::now();
  const WheelSpeeds cmd = d.command();
  d.world.setWheelTargets(cmd);
  d.world.step();
  d.measure(cmd);
  d.wall += std::chrono::steady_clock::now() - start;
}

bool Episode::finished() const { return impl_->finished; }

EpisodeSample Episode::sample() const {
  EpisodeSample s;
  s.tracking = impl_->current;
  s.obstacles = impl_->world.obstaclePoses();
  s.contacts = impl_->world.chassisContacts();
  s.stopping = impl_->world.steps() >= impl_->plan_steps;
  return s;
}

const std::vector<ExecutedRow>& Episode::rows() const { return impl_->rows; }

EpisodeMetrics Episode::metrics() const {
  const Impl& d = *impl_;
  EpisodeMetrics m;
  m.tracking = d.def.tracking;
  m.max_pos_err_m = d.max_pos;
  m.rms_pos_err_m = std::sqrt(d.sum_sq_pos / static_cast<double>(d.measured));
  m.final_pos_err_m = d.current.pos_err_m;
  m.max_heading_err_deg = radToDeg(d.max_heading);
  m.rms_heading_err_deg = radToDeg(std::sqrt(d.sum_sq_heading / static_cast<double>(d.measured)));
  m.final_heading_err_deg = radToDeg(std::abs(d.current.heading_err_rad));
  m.final_pose = d.current.pose;
  const GoalRegion& goal = d.scenario.goal;
  m.goal_pos_err_m = positionDistance(m.final_pose, goal.pose);
  const double goal_heading = goalHeadingError(goal, m.final_pose.theta);
  m.goal_heading_err_deg = radToDeg(goal_heading);
  m.goal_reached =
      m.goal_pos_err_m <= goal.position_tolerance_m && goal_heading <= goal.heading_tolerance_rad;
  m.contact_events = d.contact_events;
  m.contacts = static_cast<int>(d.contact_events.size());
  if (!d.contact_events.empty()) {
    m.first_contact_t_s = d.contact_events.front().t_s;
    m.first_contact_body = d.contact_events.front().body;
  }
  m.parked = d.parked;
  for (const ParkedRobotDisplacement& p : d.parked) {
    m.max_parked_displacement_m = std::max(m.max_parked_displacement_m, p.max_m);
  }
  m.plan_duration_s = d.reference.endTime() - d.reference.startTime();
  m.steps = d.world.steps();
  m.time_step_s = d.dt;
  m.sim_time_s = d.current.t_s;
  m.ended_at_rest = d.at_rest;
  m.wall_time_s = std::chrono::duration<double>(d.wall).count();
  return m;
}

const DynamicsWorld& Episode::world() const { return impl_->world; }

EpisodeResult runEpisode(const Scenario& scenario, const Trajectory& plan, const ExecutionDef& def,
                         const EpisodeObserver& observer, double observer_period_s) {
  Episode episode(scenario, plan, def);
  if (observer) {
    if (!(observer_period_s > 0.0)) throw Error("execution: observer period must be positive");
    observer(episode.sample());
  }
  const double dt = episode.world().timeStep();
  long next_observation = 1;  // index of the next period boundary to report
  while (!episode.finished()) {
    episode.step();
    if (!observer) continue;
    const long k = episode.world().steps();
    const bool due = static_cast<double>(k) * dt >=
                     static_cast<double>(next_observation) * observer_period_s - 1e-9 * dt;
    if (due || episode.finished()) {
      observer(episode.sample());
      while (static_cast<double>(next_observation) * observer_period_s - 1e-9 * dt <=
             static_cast<double>(k) * dt) {
        ++next_observation;
      }
    }
  }
  return {episode.metrics(), episode.rows()};
}

}  // namespace parksim
