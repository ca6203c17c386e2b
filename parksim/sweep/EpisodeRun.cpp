#include "parksim/sweep/EpisodeRun.h"

#include <chrono>

#include "parksim/core/Error.h"
#include "parksim/pipeline/EpisodePipeline.h"
#include "parksim/results/MetricsFile.h"
#include "parksim/sweep/EpisodeSetup.h"

namespace parksim {
namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

// The sweep's recording choices as the pipeline's: which episodes keep files, at which row
// rate, and the film of a failure.
void applyRecord(const EpisodeRunDef& def, const std::string& dir, EpisodeRequest& r) {
  r.out_dir = dir;
  r.record.files = def.record.executed_csv;
  r.record.executed_rate_hz = def.record.executed_rate_hz;
  r.record.format = def.record.format;
  if (!def.record.film_failures) return;
  if (def.film_mutex == nullptr) throw Error("runSweepEpisode: filming needs a film_mutex");
  r.film.when = FilmWhen::kOnFailure;
  r.film.lock = def.film_mutex;
  r.film.frames.fps = def.record.film_fps;
  r.film.frames.width_px = def.record.film_width_px;
  r.film.frames.height_px = def.record.film_height_px;
  r.film.frames.view = frameViewFromString(def.record.film_view);
  r.film.frames.video = def.record.film_video;
}

void addPlanColumns(const EpisodeOutcome& out, nlohmann::ordered_json& row) {
  const PlanResult& plan = *out.plan;
  const Scenario& scenario = out.world->scenario;
  row["plan_status"] = toString(plan.status);
  row["plan_solved"] = plan.solved();
  row["plan_max_iterations"] = out.plan_setup.search.max_iterations;
  row["plan_iterations"] = plan.stats.iterations;
  row["plan_tree_size"] = plan.stats.tree_size;
  row["plan_goal_tree_size"] = plan.stats.goal_tree_size;
  row["plan_collision_queries"] = plan.stats.collision_queries;
  if (plan.solved()) {
    // A path cost, m; a planner that minimises duration (time-a-star) has its cost in
    // plan_duration_s, and this column stays empty rather than hold seconds.
    if (plan.objective == PlanObjective::kPathCost) row["plan_cost_m"] = plan.cost;
    row["plan_path_length_m"] = plan.trajectory.pathLength(scenario.robot);
    row["plan_duration_s"] = plan.trajectory.duration();
    row["plan_cusps"] = plan.trajectory.cusps(scenario.robot);
  }
  if (plan.stats.first_solution_iteration >= 0) {
    row["plan_first_solution_iteration"] = plan.stats.first_solution_iteration;
  }
}

void addSimulationColumns(const EpisodeOutcome& out, nlohmann::ordered_json& row) {
  const EpisodeMetrics& m = out.episode.metrics;
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
}

void addTimingColumns(const EpisodeOutcome& out, Clock::time_point t0,
                      nlohmann::ordered_json& row) {
  const PlanResult& plan = *out.plan;
  row["plan_time_s"] = plan.stats.times.total_s;
  if (plan.stats.first_solution_s >= 0.0) {
    row["plan_first_solution_s"] = plan.stats.first_solution_s;
  }
  if (out.driven()) row["sim_wall_s"] = out.episode.metrics.wall_time_s;
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
}

}  // namespace

nlohmann::ordered_json runSweepEpisode(const SweepEpisode& episode, const EpisodeRunDef& def) {
  const Clock::time_point t0 = Clock::now();
  static const ToleranceOverrides kNoOverrides;
  EpisodeRequest request = episodeRequest(episode.params, episode.world,
                                          episode.tolerance ? *episode.tolerance : kNoOverrides);
  applyRecord(def, def.episodes_dir + "/" + episode.id, request);
  const EpisodeOutcome out = runEpisodePipeline(request);

  nlohmann::ordered_json row;
  row["episode_id"] = episode.id;
  appendParamColumns(episode.params, row);
  row["status"] = toString(out.verdict.status);
  row["met_tolerance"] = out.verdict.met();
  row["failure"] = out.verdict.reason;
  addPlanColumns(out, row);
  if (out.driven()) addSimulationColumns(out, row);
  addTimingColumns(out, t0, row);
  // Which content of the world file the episode ran on: its name alone (in the id) cannot tell
  // an edited file from the one an earlier run used.
  row["world_hash"] = episode.world->content_hash;
  return row;
}

}  // namespace parksim
