#include "parksim/results/tables/EpisodeRecord.h"

#include <algorithm>
#include <array>
#include <utility>
#include <vector>

namespace parksim {
namespace {

using Json = nlohmann::ordered_json;
using F = EpisodeFacts;

// A key of the plan's summary (plan.json), as it is there.
Json fromSummary(const F& f, const char* key) {
  if (f.plan_summary == nullptr) return nullptr;
  const auto it = f.plan_summary->find(key);
  return it != f.plan_summary->end() ? Json(*it) : Json();
}

// A member of the measured metrics, as it is there.
template <auto Member>
Json metric(const F& f) {
  return f.metrics != nullptr ? Json(f.metrics->*Member) : Json();
}

template <auto Member>
Json planStat(const F& f) {
  return f.plan != nullptr ? Json(f.plan->stats.*Member) : Json();
}

Json contactBodies(const EpisodeMetrics& m) {
  Json bodies = Json::array();
  for (const ContactEvent& e : m.contact_events) {
    if (std::find(bodies.begin(), bodies.end(), e.body) == bodies.end()) bodies.push_back(e.body);
  }
  return bodies;
}

constexpr unsigned kTable = 1;
constexpr unsigned kCsv = 2;
constexpr unsigned kJUnit = 4;
constexpr unsigned kPerName = 8;
constexpr unsigned kColumn = kTable | kCsv;

constexpr EpisodeField field(std::string_view key, std::string_view metrics_key, FieldGroup group,
                             FieldType type, std::string_view unit, std::string_view meaning,
                             FieldReader read, unsigned where) {
  return {key,
          metrics_key,
          group,
          type,
          unit,
          meaning,
          read,
          (where & kCsv) != 0,
          (where & kJUnit) != 0,
          (where & kPerName) != 0};
}

using G = FieldGroup;
using T = FieldType;

// The record. Each entry: table key, metrics.json key, group, type, unit, meaning, reader,
// where it goes. Keys are the names the files have always used: where the table and
// metrics.json name one quantity differently (sim_wall_s / wall_time_s), both are here.
const std::array kFields = {
    // identity and parameters: the sweep's (sweep/spec/EpisodeParams.h) values
    field("episode_id", "", G::kIdentity, T::kString, "",
          "16 hex digits: the hash of the episode's parameters (docs/sweeps.md, \"Episode ids\")",
          nullptr, kColumn | kJUnit),
    field("world", "", G::kParameter, T::kString, "", "the world's scenario name", nullptr,
          kColumn | kJUnit),
    field("world_file", "", G::kParameter, T::kString, "",
          "the world file, as the spec names it (relative to the spec's folder)", nullptr,
          kColumn | kJUnit),
    field("planner", "", G::kParameter, T::kString, "", "the planner", nullptr, kColumn | kJUnit),
    field("steering", "", G::kParameter, T::kString, "", "the tree planners' steering", nullptr,
          kColumn | kJUnit),
    field("smooth", "", G::kParameter, T::kBoolean, "",
          "time-optimal shortcuts and fillets after the planner", nullptr, kColumn | kJUnit),
    field("seed", "", G::kParameter, T::kInteger, "", "the planner's seed", nullptr,
          kColumn | kJUnit),
    field("max_iterations", "", G::kParameter, T::kInteger, "",
          "the iteration budget asked for; 0: auto, the lot's (used: plan_max_iterations)",
          nullptr, kColumn | kJUnit),
    field("tracking", "tracking", G::kParameter, T::kString, "", "closed or open loop",
          [](const F& f) { return f.metrics ? Json(toString(f.metrics->tracking)) : Json(); },
          kColumn | kJUnit),
    field("controller", "controller", G::kParameter, T::kString, "",
          "the controller of closed-loop tracking, by its registered name",
          [](const F& f) { return f.metrics ? Json(f.metrics->controller) : Json(); },
          kColumn | kJUnit),
    field("timing", "", G::kParameter, T::kString, "", "how the plan is timed", nullptr,
          kColumn | kJUnit),
    field("realism", "", G::kParameter, T::kString, "",
          "world (the world file's realism: section) or a preset", nullptr, kColumn | kJUnit),
    field("noise_seed", "noise_seed", G::kParameter, T::kInteger, "",
          "seed of the realism's random draws", &metric<&EpisodeMetrics::noise_seed>,
          kColumn | kJUnit),
    field("start_dx_m", "", G::kParameter, T::kNumber, "m", "offset of the start, x", nullptr,
          kColumn | kJUnit),
    field("start_dy_m", "", G::kParameter, T::kNumber, "m", "offset of the start, y", nullptr,
          kColumn | kJUnit),
    field("start_dyaw_deg", "", G::kParameter, T::kNumber, "deg",
          "offset of the start, heading (counter-clockwise)", nullptr, kColumn | kJUnit),
    field("goal_dx_m", "", G::kParameter, T::kNumber, "m", "offset of the goal, x", nullptr,
          kColumn | kJUnit),
    field("goal_dy_m", "", G::kParameter, T::kNumber, "m", "offset of the goal, y", nullptr,
          kColumn | kJUnit),
    field("goal_dyaw_deg", "", G::kParameter, T::kNumber, "deg", "offset of the goal, heading",
          nullptr, kColumn | kJUnit),
    field("sample", "", G::kParameter, T::kInteger, "",
          "the draw of a sampled spec (0, 1, ...); empty without samples:", nullptr,
          kColumn | kJUnit),

    // outcome
    field("status", "status", G::kOutcome, T::kString, "",
          "the verdict's status: met, or the first check that failed (pipeline/Verdict.h's "
          "EpisodeStatus)",
          [](const F& f) { return f.judged ? Json(f.status) : Json(); }, kColumn | kJUnit),
    field("met_tolerance", "met_tolerance", G::kOutcome, T::kBoolean, "",
          "solved, driven and within every bound",
          [](const F& f) { return f.judged ? Json(f.met) : Json(); }, kColumn),
    field("failure", "failure", G::kOutcome, T::kString, "",
          "the verdict's one line; empty when met",
          [](const F& f) { return f.judged ? Json(f.failure) : Json(); }, kColumn),

    // plan: plan.json's statistics (metrics.json has every key of plan.json as plan_<key>)
    field("plan_status", "plan_status", G::kPlan, T::kString, "",
          "the planner's status (plan_invalid: its plan failed the check; planner_error: it "
          "failed)",
          [](const F& f) { return fromSummary(f, "status"); }, kColumn),
    field("plan_solved", "plan_solved", G::kPlan, T::kBoolean, "",
          "a plan that may be driven was found",
          [](const F& f) { return fromSummary(f, "solved"); }, kColumn),
    field("plan_max_iterations", "plan_max_iterations", G::kPlan, T::kInteger, "",
          "the iteration budget used", [](const F& f) { return fromSummary(f, "max_iterations"); },
          kColumn),
    field("plan_iterations", "plan_iterations", G::kPlan, T::kInteger, "",
          "iterations (node expansions for the A* planners)",
          [](const F& f) { return fromSummary(f, "iterations"); }, kColumn),
    field("plan_tree_size", "plan_tree_size", G::kPlan, T::kInteger, "", "nodes of the (start) tree",
          [](const F& f) { return fromSummary(f, "tree_size"); }, kColumn),
    field("plan_goal_tree_size", "plan_goal_tree_size", G::kPlan, T::kInteger, "",
          "nodes of the goal tree (bidirectional planners)",
          [](const F& f) { return fromSummary(f, "goal_tree_size"); }, kColumn),
    field("plan_collision_queries", "plan_collision_queries", G::kPlan, T::kInteger, "",
          "footprint queries", [](const F& f) { return fromSummary(f, "collision_queries"); },
          kColumn),
    field("plan_cost_m", "plan_cost_m", G::kPlan, T::kNumber, "m",
          "path cost; empty for planners that minimise duration (time-a-star: plan_duration_s)",
          [](const F& f) { return fromSummary(f, "cost_m"); }, kColumn),
    field("plan_path_length_m", "plan_path_length_m", G::kPlan, T::kNumber, "m",
          "length of the planned path", [](const F& f) { return fromSummary(f, "path_length_m"); },
          kColumn),
    field("plan_duration_s", "plan_duration_s", G::kPlan, T::kNumber, "s",
          "duration of the timed plan",
          [](const F& f) {
            Json v = fromSummary(f, "duration_s");
            return v.is_null() ? metric<&EpisodeMetrics::plan_duration_s>(f) : v;
          },
          kColumn),
    field("plan_cusps", "plan_cusps", G::kPlan, T::kInteger, "", "changes of driving direction",
          [](const F& f) { return fromSummary(f, "cusps"); }, kColumn),
    field("plan_first_solution_iteration", "plan_first_solution_iteration", G::kPlan, T::kInteger,
          "", "iterations done at the first solution",
          [](const F& f) { return fromSummary(f, "first_solution_iteration"); }, kColumn),

    // simulation (sim/episode/EpisodeMetrics.h; docs/simulation.md, "Measurement")
    field("max_pos_err_m", "max_pos_err_m", G::kSimulation, T::kNumber, "m",
          "largest tracking error against the plan", &metric<&EpisodeMetrics::max_pos_err_m>,
          kColumn),
    field("rms_pos_err_m", "rms_pos_err_m", G::kSimulation, T::kNumber, "m",
          "RMS tracking error over every step", &metric<&EpisodeMetrics::rms_pos_err_m>, kColumn),
    field("final_pos_err_m", "final_pos_err_m", G::kSimulation, T::kNumber, "m",
          "tracking error at the end, against the plan's last pose",
          &metric<&EpisodeMetrics::final_pos_err_m>, kColumn),
    field("max_heading_err_deg", "max_heading_err_deg", G::kSimulation, T::kNumber, "deg",
          "largest heading error against the plan", &metric<&EpisodeMetrics::max_heading_err_deg>,
          kColumn),
    field("rms_heading_err_deg", "rms_heading_err_deg", G::kSimulation, T::kNumber, "deg",
          "RMS heading error", &metric<&EpisodeMetrics::rms_heading_err_deg>, kColumn),
    field("final_heading_err_deg", "final_heading_err_deg", G::kSimulation, T::kNumber, "deg",
          "heading error at the end", &metric<&EpisodeMetrics::final_heading_err_deg>, kColumn),
    field("final_x_m", "final_x_m", G::kSimulation, T::kNumber, "m", "final pose, x",
          [](const F& f) { return f.metrics ? Json(f.metrics->final_pose.x) : Json(); }, kColumn),
    field("final_y_m", "final_y_m", G::kSimulation, T::kNumber, "m", "final pose, y",
          [](const F& f) { return f.metrics ? Json(f.metrics->final_pose.y) : Json(); }, kColumn),
    field("final_theta_rad", "final_theta_rad", G::kSimulation, T::kNumber, "rad",
          "final pose, heading",
          [](const F& f) { return f.metrics ? Json(f.metrics->final_pose.theta) : Json(); },
          kColumn),
    field("goal_pos_err_m", "goal_pos_err_m", G::kSimulation, T::kNumber, "m",
          "final pose against the world's goal", &metric<&EpisodeMetrics::goal_pos_err_m>,
          kColumn),
    field("goal_heading_err_deg", "goal_heading_err_deg", G::kSimulation, T::kNumber, "deg",
          "final heading against the goal's (either heading when the goal allows it)",
          &metric<&EpisodeMetrics::goal_heading_err_deg>, kColumn),
    field("goal_reached", "goal_reached", G::kSimulation, T::kBoolean, "",
          "within the world's goal tolerance at the end", &metric<&EpisodeMetrics::goal_reached>,
          kColumn),
    field("contacts", "contacts", G::kSimulation, T::kInteger, "",
          "contact events between the chassis and anything but the ground",
          &metric<&EpisodeMetrics::contacts>, kColumn),
    field("first_contact_t_s", "first_contact_t_s", G::kSimulation, T::kNumber, "s",
          "time of the first contact event; -1 when none",
          &metric<&EpisodeMetrics::first_contact_t_s>, kColumn),
    field("first_contact_body", "first_contact_body", G::kSimulation, T::kString, "",
          "what it touched first; empty when nothing",
          &metric<&EpisodeMetrics::first_contact_body>, kColumn),
    field("contact_bodies", "contact_bodies", G::kSimulation, T::kList, "",
          "every body touched, in first-touched order ('|'-separated in results.csv)",
          [](const F& f) { return f.metrics ? contactBodies(*f.metrics) : Json(); }, kColumn),
    field("max_parked_displacement_m", "max_parked_displacement_m", G::kSimulation, T::kNumber,
          "m", "largest horizontal displacement of a parked robot's centre",
          &metric<&EpisodeMetrics::max_parked_displacement_m>, kColumn),
    field("sim_time_s", "sim_time_s", G::kSimulation, T::kNumber, "s", "simulated time",
          &metric<&EpisodeMetrics::sim_time_s>, kColumn),
    field("steps", "steps", G::kSimulation, T::kInteger, "", "physics steps",
          &metric<&EpisodeMetrics::steps>, kColumn),
    field("", "time_step_s", G::kSimulation, T::kNumber, "s", "the physics step",
          &metric<&EpisodeMetrics::time_step_s>, 0),
    field("ended_at_rest", "ended_at_rest", G::kSimulation, T::kBoolean, "",
          "the robot came to rest (false: the time limit ended it)",
          &metric<&EpisodeMetrics::ended_at_rest>, kColumn),

    field("parked_displacement_m", "parked_displacement_m", G::kSimulation, T::kNumber, "m",
          "the same per parked robot, as parked_displacement_m.<name>",
          [](const F& f) {
            if (f.metrics == nullptr) return Json();
            Json byName = Json::object();
            for (const ParkedRobotDisplacement& p : f.metrics->parked) byName[p.name] = p.max_m;
            return byName;
          },
          kTable | kPerName),

    // realism layers (docs/realism.md); the ideal robot's: truth, zeros, the nominal robot
    field("", "realism", G::kRealism, T::kString, "",
          "the realism the robot had: its preset, or the world's realism: section's name",
          &metric<&EpisodeMetrics::realism>, 0),
    field("estimator", "estimator", G::kRealism, T::kString, "",
          "what the controller's pose estimate is (truth for the ideal robot)",
          &metric<&EpisodeMetrics::estimator>, kColumn),
    field("max_est_pos_err_m", "max_est_pos_err_m", G::kRealism, T::kNumber, "m",
          "largest error of the estimate against the true pose",
          &metric<&EpisodeMetrics::max_est_pos_err_m>, kColumn),
    field("rms_est_pos_err_m", "rms_est_pos_err_m", G::kRealism, T::kNumber, "m",
          "RMS error of the estimate", &metric<&EpisodeMetrics::rms_est_pos_err_m>, kColumn),
    field("max_est_heading_err_deg", "max_est_heading_err_deg", G::kRealism, T::kNumber, "deg",
          "largest heading error of the estimate",
          &metric<&EpisodeMetrics::max_est_heading_err_deg>, kColumn),
    field("final_est_pos_err_m", "final_est_pos_err_m", G::kRealism, T::kNumber, "m",
          "error of the estimate at the end", &metric<&EpisodeMetrics::final_est_pos_err_m>,
          kColumn),
    field("max_slip_mps", "max_slip_mps", G::kRealism, T::kNumber, "m/s",
          "largest wheel slip (rim speed minus ground speed), both wheels",
          &metric<&EpisodeMetrics::max_slip_mps>, kColumn),
    field("rms_slip_mps", "rms_slip_mps", G::kRealism, T::kNumber, "m/s", "RMS wheel slip",
          &metric<&EpisodeMetrics::rms_slip_mps>, kColumn),
    field("slip_fraction", "slip_fraction", G::kRealism, T::kNumber, "",
          "share of wheel-steps slipping by more than 1 mm/s",
          &metric<&EpisodeMetrics::slip_fraction>, kColumn),
    field("max_motor_torque_nm", "max_motor_torque_nm", G::kRealism, T::kNumber, "N m",
          "largest motor torque", &metric<&EpisodeMetrics::max_motor_torque_nm>, kColumn),
    field("max_motor_effort", "max_motor_effort", G::kRealism, T::kNumber, "",
          "largest motor effort (share of the supply)", &metric<&EpisodeMetrics::max_motor_effort>,
          kColumn),
    field("pose_samples_dropped", "pose_samples_dropped", G::kRealism, T::kInteger, "",
          "pose samples the sensor dropped", &metric<&EpisodeMetrics::pose_samples_dropped>,
          kColumn),
    field("true_left_radius_m", "true_left_radius_m", G::kRealism, T::kNumber, "m",
          "the left wheel's radius as built (the drawn calibration)",
          &metric<&EpisodeMetrics::true_left_radius_m>, kColumn),
    field("true_right_radius_m", "true_right_radius_m", G::kRealism, T::kNumber, "m",
          "the right wheel's radius as built", &metric<&EpisodeMetrics::true_right_radius_m>,
          kColumn),
    field("true_track_m", "true_track_m", G::kRealism, T::kNumber, "m",
          "the wheel track as built", &metric<&EpisodeMetrics::true_track_m>, kColumn),
    field("left_motor_gain", "left_motor_gain", G::kRealism, T::kNumber, "",
          "the left motor's drawn gain", &metric<&EpisodeMetrics::left_motor_gain>, kColumn),
    field("right_motor_gain", "right_motor_gain", G::kRealism, T::kNumber, "",
          "the right motor's drawn gain", &metric<&EpisodeMetrics::right_motor_gain>, kColumn),
    field("pose_samples_taken", "pose_samples_taken", G::kRealism, T::kInteger, "",
          "pose samples the sensor took", &metric<&EpisodeMetrics::pose_samples_taken>, kColumn),
    field("pose_samples_received", "pose_samples_received", G::kRealism, T::kInteger, "",
          "pose samples the controller received",
          &metric<&EpisodeMetrics::pose_samples_received>, kColumn),

    // timing: wall clock, differs between runs of the same episode
    field("plan_time_s", "plan_planning_time_s", G::kTiming, T::kNumber, "s", "planning wall time",
          [](const F& f) { return fromSummary(f, "planning_time_s"); }, kColumn),
    field("plan_first_solution_s", "plan_first_solution_s", G::kTiming, T::kNumber, "s",
          "wall time to the first solution",
          [](const F& f) { return fromSummary(f, "first_solution_s"); }, kColumn),
    field("sim_wall_s", "wall_time_s", G::kTiming, T::kNumber, "s",
          "wall time of stepping and measuring", &metric<&EpisodeMetrics::wall_time_s>, kColumn),
    field("", "real_time_factor", G::kTiming, T::kNumber, "",
          "simulated time over sim_wall_s",
          [](const F& f) {
            if (f.metrics == nullptr) return Json();
            const EpisodeMetrics& m = *f.metrics;
            return Json(m.wall_time_s > 0.0 ? m.sim_time_s / m.wall_time_s : 0.0);
          },
          0),
    field("plan_cost_history", "", G::kTiming, T::kList, "",
          "[time_s, iteration, cost_m] per improvement of the plan's cost",
          [](const F& f) {
            if (f.plan == nullptr) return Json();
            Json history = Json::array();
            for (const CostSample& c : f.plan->cost_history) {
              history.push_back({c.time_s, c.iteration, c.cost});
            }
            return history;
          },
          kTable),
    field("plan_phase_times_s", "", G::kTiming, T::kObject, "s",
          "planning time per phase, every phase of plan.json's phase_times_s",
          [](const F& f) {
            if (f.plan == nullptr) return Json();
            Json phases = Json::object();
            // In phaseTimeList's order (an ordered row keeps it).
            for (const auto& [name, s] : phaseTimeList(f.plan->stats.times)) phases[name] = s;
            return phases;
          },
          kTable),
    field("episode_wall_s", "", G::kTiming, T::kNumber, "s",
          "wall time of the whole episode (plan, drive, files)",
          [](const F& f) { return f.episode_wall_s >= 0.0 ? Json(f.episode_wall_s) : Json(); },
          kColumn),

    // provenance: the world file's content (read here) and the build (the table writer's)
    field("world_hash", "", G::kProvenance, T::kString, "",
          "16 hex digits: FNV-1a of the world file's bytes",
          [](const F& f) { return f.world_hash.empty() ? Json() : Json(f.world_hash); }, kColumn),
    field("plugins", "", G::kProvenance, T::kString, "",
          "the plugins loaded, each 'name version file-hash', joined by '; ' (empty: none): a "
          "resumed table must be run with the same",
          nullptr, kColumn),
    field("parksim_version", "", G::kProvenance, T::kString, "", "as parksim --version", nullptr,
          kColumn),
    field("git_commit", "", G::kProvenance, T::kString, "", "the commit parksim was built from",
          nullptr, kColumn),
    field("git_dirty", "", G::kProvenance, T::kBoolean, "",
          "tracked files differed from that commit", nullptr, kColumn),
    field("build_type", "", G::kProvenance, T::kString, "", "Release, RelWithDebInfo+asan+ubsan, ...",
          nullptr, kColumn),
    field("compiler", "", G::kProvenance, T::kString, "", "the compiler", nullptr, kColumn),
    field("bullet_precision", "", G::kProvenance, T::kString, "", "float or double", nullptr,
          kColumn),
    field("host", "", G::kProvenance, T::kString, "", "the machine that ran the episode", nullptr,
          kColumn),

    field("row_checksum", "", G::kSeal, T::kString, "",
          "16 hex digits sealing the row (docs/sweeps.md, \"Integrity\"); always last", nullptr,
          kColumn),
};

}  // namespace

std::span<const EpisodeField> episodeFields() { return kFields; }

const EpisodeField* findField(std::string_view key) {
  // Sorted by key once: readers look up every key of every row (100,000 rows in seconds).
  static const std::vector<std::pair<std::string_view, const EpisodeField*>> index = [] {
    std::vector<std::pair<std::string_view, const EpisodeField*>> v;
    for (const EpisodeField& f : kFields) {
      if (!f.key.empty()) v.emplace_back(f.key, &f);
    }
    std::sort(v.begin(), v.end());
    return v;
  }();
  const auto it =
      std::lower_bound(index.begin(), index.end(), key,
                       [](const auto& entry, std::string_view k) { return entry.first < k; });
  if (it != index.end() && it->first == key) return it->second;
  const std::size_t dot = key.find('.');
  if (dot == std::string_view::npos || dot + 1 == key.size()) return nullptr;
  const EpisodeField* family = findField(key.substr(0, dot));
  return family != nullptr && family->per_name ? family : nullptr;
}

bool isSetKey(std::string_view key) { return !key.empty() && findField(key) == nullptr; }

bool isReplicateKey(std::string_view key) {
  return key == "seed" || key == "noise_seed" || key == "sample";
}

void appendRecord(const EpisodeFacts& facts, nlohmann::ordered_json& row) {
  for (const EpisodeField& f : kFields) {
    if (f.key.empty() || f.read == nullptr || f.group == FieldGroup::kParameter) continue;
    const Json value = f.read(facts);
    if (value.is_null()) continue;
    if (!f.per_name) {
      row[std::string(f.key)] = value;
      continue;
    }
    for (const auto& [name, v] : value.items()) row[std::string(f.key) + "." + name] = v;
  }
}

nlohmann::json metricsRecord(const EpisodeFacts& facts) {
  nlohmann::json j = nlohmann::json::object();
  for (const EpisodeField& f : kFields) {
    if (f.metrics_key.empty() || f.read == nullptr) continue;
    Json value = f.read(facts);
    if (value.is_null()) continue;
    if (!f.per_name) {
      j[std::string(f.metrics_key)] = std::move(value);
      continue;
    }
    for (const auto& [name, v] : value.items()) j[std::string(f.metrics_key) + "." + name] = v;
  }
  return j;
}

std::size_t setColumnsPosition() {
  std::size_t n = 0;
  for (const EpisodeField& f : kFields) {
    if (f.group > FieldGroup::kParameter) break;
    n += f.csv ? 1 : 0;
  }
  return n;
}

std::vector<std::string> recordColumns(const std::vector<std::string>& set_columns) {
  std::vector<std::string> columns;
  for (const EpisodeField& f : kFields) {
    if (f.csv) columns.emplace_back(f.key);
  }
  columns.insert(columns.begin() + static_cast<long>(setColumnsPosition()), set_columns.begin(),
                 set_columns.end());
  return columns;
}

namespace {

const char* groupName(FieldGroup g) {
  switch (g) {
    case FieldGroup::kIdentity: return "identity";
    case FieldGroup::kParameter: return "parameters";
    case FieldGroup::kOutcome: return "outcome";
    case FieldGroup::kPlan: return "plan";
    case FieldGroup::kSimulation: return "simulation (empty when nothing was driven)";
    case FieldGroup::kRealism: return "realism layers";
    case FieldGroup::kTiming: return "timing (wall clock; differs between runs)";
    case FieldGroup::kProvenance: return "provenance";
    case FieldGroup::kSeal: return "seal";
  }
  return "?";
}

}  // namespace

std::string recordColumnsMarkdown() {
  std::string s = "| group | column | unit | meaning |\n|---|---|---|---|\n";
  const auto row = [&s](FieldGroup g, std::string_view column, std::string_view unit,
                        std::string_view meaning) {
    s += "| ";
    s += groupName(g);
    s += " | ";
    s += column;
    s += " | ";
    s += unit;
    s += " | ";
    s += meaning;
    s += " |\n";
  };
  std::size_t columns = 0;
  for (const EpisodeField& f : kFields) {
    if (!f.csv) continue;
    std::string meaning(f.meaning);
    if (!f.metrics_key.empty() && f.metrics_key != f.key) {
      meaning += " (metrics.json: `" + std::string(f.metrics_key) + "`)";
    }
    row(f.group, "`" + std::string(f.key) + "`", f.unit, meaning);
    if (++columns == setColumnsPosition()) {
      row(FieldGroup::kParameter, "`<path>`", "",
          "one column per `set:` path (its value), sorted by path (\"Parameter studies\")");
    }
  }
  s += "\n`results.jsonl` holds every column and also:\n\n";
  for (const EpisodeField& f : kFields) {
    if (f.key.empty() || f.csv) continue;
    s += "- `" + std::string(f.key) + (f.per_name ? ".<name>" : "") + "`";
    if (!f.unit.empty()) s += " (" + std::string(f.unit) + ")";
    s += ": " + std::string(f.meaning) + "\n";
  }
  return s;
}

}  // namespace parksim
