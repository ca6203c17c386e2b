#include "parksim/sweep/EpisodeRun.h"

#include <chrono>
#include <climits>
#include <cmath>
#include <cstdio>
#include <memory>

#include "parksim/collision/BulletCollisionWorld.h"
#include "parksim/core/AtomicFile.h"
#include "parksim/core/Error.h"
#include "parksim/renders/FrameRecorder.h"
#include "parksim/sim/Episode.h"
#include "parksim/sim/EpisodeFiles.h"
#include "parksim/sweep/EpisodeSetup.h"

namespace parksim {
namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

// Why the episode failed its tolerance, as (status, one line); kStatusMet and "" when it met it.
std::pair<const char*, std::string> judge(const Scenario& scenario, const EpisodeMetrics& m,
                                          const TrackingTolerance& tolerance) {
  char text[320];
  if (m.contacts > tolerance.max_contacts) {
    std::snprintf(text, sizeof text, "touched %s at %.3f s (%d contact event%s)",
                  m.first_contact_body.c_str(), m.first_contact_t_s, m.contacts,
                  m.contacts == 1 ? "" : "s");
    return {kStatusContact, text};
  }
  if (!m.goal_reached) {
    std::snprintf(text, sizeof text,
                  "goal not reached: ended %.3f mm / %.3f deg from the goal (tolerance %.3f mm / "
                  "%.3f deg)",
                  m.goal_pos_err_m * 1e3, m.goal_heading_err_deg,
                  scenario.goal.position_tolerance_m * 1e3,
                  radToDeg(scenario.goal.heading_tolerance_rad));
    return {kStatusGoalMissed, text};
  }
  const std::vector<std::string> violations = checkTracking(tolerance, m);
  if (!violations.empty()) {
    return {kStatusToleranceMissed, "tracking tolerance not met: " + joinViolations(violations)};
  }
  return {kStatusMet, ""};
}

// executed.csv rows every this many steps: the recording rate, or (when nothing is recorded)
// only the first and last rows the episode always keeps.
int csvStride(const RecordDef& record, double time_step_s) {
  if (record.executed_csv == ExecutedCsvPolicy::kNone) return INT_MAX / 2;
  return std::max(1, static_cast<int>(std::lround(1.0 / (record.executed_rate_hz * time_step_s))));
}

void film(const EpisodeSetup& setup, const Trajectory& plan, const RecordDef& record,
          const std::string& dir) {
  FrameDef def;
  def.fps = record.film_fps;
  def.width_px = record.film_width_px;
  def.height_px = record.film_height_px;
  def.view = frameViewFromString(record.film_view);
  def.out_dir = dir;
  def.video = record.film_video;
  ExecutionDef exec = setup.execution;
  // Before the first frame, as run --frames does: not after rendering 50,000 of them.
  checkFrameLimits(def, plan.duration() + exec.max_stop_time_s);
  FrameRecorder recorder(setup.scenario, def);
  recorder.setPlan(plan);
  const EpisodeObserver observer = [&recorder](const EpisodeSample& s) {
    FrameInput in;
    in.t_s = s.tracking.t_s;
    in.pose = s.tracking.pose;
    in.reference = s.tracking.reference;
    in.position_error_m = s.tracking.pos_err_m;
    in.heading_error_rad = s.tracking.heading_err_rad;
    in.obstacle_poses = s.obstacles;
    in.contacts = s.contacts;
    recorder.addFrame(in);
  };
  exec.csv_stride_steps = INT_MAX / 2;
  (void)runEpisode(setup.scenario, plan, exec, observer, 1.0 / record.film_fps);
  (void)recorder.finish();
}

}  // namespace

nlohmann::ordered_json runSweepEpisode(const SweepEpisode& episode, const EpisodeRunDef& def) {
  const Clock::time_point t0 = Clock::now();
  static const ToleranceOverrides kNoOverrides;
  const EpisodeSetup setup = setupEpisode(episode.params, *episode.world,
                                          episode.tolerance ? *episode.tolerance : kNoOverrides);
  const Scenario& scenario = setup.scenario;

  nlohmann::ordered_json row;
  row["episode_id"] = episode.id;
  appendParamColumns(episode.params, row);
  // Placeholders keep the outcome right after the parameters in every row.
  row["status"] = kStatusMet;
  row["met_tolerance"] = false;
  row["failure"] = "";

  const BulletCollisionWorld collision(scenario);
  const PlanResult plan = planScenario(scenario, collision, setup.plan);
  row["plan_status"] = toString(plan.status);
  row["plan_solved"] = plan.solved();
  row["plan_iterations"] = plan.stats.iterations;
  row["plan_tree_size"] = plan.stats.tree_size;
  row["plan_goal_tree_size"] = plan.stats.goal_tree_size;
  row["plan_collision_queries"] = plan.stats.collision_queries;
  if (plan.solved()) {
    row["plan_cost_m"] = plan.cost;
    row["plan_path_length_m"] = plan.trajectory.pathLength(scenario.robot);
    row["plan_duration_s"] = plan.trajectory.duration();
    row["plan_cusps"] = plan.trajectory.cusps(scenario.robot);
  }
  if (plan.stats.first_solution_iteration >= 0) {
    row["plan_first_solution_iteration"] = plan.stats.first_solution_iteration;
  }

  const std::string dir = def.episodes_dir + "/" + episode.id;
  bool met = false;
  double sim_wall_s = 0.0;
  if (!plan.solved()) {
    row["status"] = kStatusPlanFailed;
    row["failure"] = std::string("plan ") + toString(plan.status) + ": " + plan.message;
  } else {
    ExecutionDef exec = setup.execution;
    exec.csv_stride_steps = csvStride(def.record, scenario.physics.time_step_s);
    const EpisodeResult result = runEpisode(scenario, plan.trajectory, exec);
    const EpisodeMetrics& m = result.metrics;
    sim_wall_s = m.wall_time_s;
    const nlohmann::json mj = metricsToJson(m);
    for (const char* key : {"max_pos_err_m",
                            "rms_pos_err_m",
                            "final_pos_err_m",
                            "max_heading_err_deg",
                            "rms_heading_err_deg",
                            "final_heading_err_deg",
                            "final_x_m",
                            "final_y_m",
                            "final_theta_rad",
                            "goal_pos_err_m",
                            "goal_heading_err_deg",
                            "goal_reached",
                            "contacts",
                            "first_contact_t_s",
                            "first_contact_body",
                            "contact_bodies",
                            "max_parked_displacement_m",
                            "sim_time_s",
                            "steps",
                            "ended_at_rest"}) {
      row[key] = mj.at(key);
    }
    for (const ParkedRobotDisplacement& p : m.parked) {
      row["parked_displacement_m." + p.name] = p.max_m;
    }
    const auto [status, failure] = judge(scenario, m, setup.tolerance);
    met = failure.empty();
    row["status"] = status;
    row["failure"] = failure;
    const bool keep_csv = def.record.executed_csv == ExecutedCsvPolicy::kAll ||
                          (def.record.executed_csv == ExecutedCsvPolicy::kFailures && !met);
    if (keep_csv) {
      ensureDirectory(dir);
      writeExecutedCsv(dir + "/executed.csv", result.rows, exec.realism.active());
      writeTrajectoryCsv(dir + "/trajectory.csv", plan.trajectory, scenario.robot);
    }
    if (def.record.film_failures && !met) {
      if (def.film_mutex == nullptr) throw Error("runSweepEpisode: filming needs a film_mutex");
      const std::lock_guard<std::mutex> lock(*def.film_mutex);
      film(setup, plan.trajectory, def.record, dir);
    }
  }
  row["met_tolerance"] = met;

  row["plan_time_s"] = plan.stats.times.total_s;
  if (plan.stats.first_solution_s >= 0.0)
    row["plan_first_solution_s"] = plan.stats.first_solution_s;
  if (plan.solved()) row["sim_wall_s"] = sim_wall_s;
  nlohmann::ordered_json history = nlohmann::ordered_json::array();
  for (const CostSample& c : plan.cost_history) history.push_back({c.time_s, c.iteration, c.cost});
  row["plan_cost_history"] = history;
  const PhaseTimes& t = plan.stats.times;
  row["plan_phase_times_s"] = {
      {"sampling", t.sampling_s},      {"nearest_neighbour", t.nearest_s},
      {"steering", t.steering_s},      {"collision_checking", t.collision_s},
      {"goal_checks", t.goal_check_s}, {"rewiring", t.rewiring_s},
      {"connection", t.connection_s},  {"smoothing", t.smoothing_s}};
  row["episode_wall_s"] = secondsSince(t0);
  return row;
}

}  // namespace parksim
