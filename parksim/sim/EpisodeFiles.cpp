#include "parksim/sim/EpisodeFiles.h"

#include <algorithm>
#include <fstream>
#include <iterator>
#include <sstream>

#include "parksim/core/AtomicFile.h"
#include "parksim/core/Error.h"
#include "parksim/core/NumberFormat.h"

namespace parksim {

std::string executedCsv(const std::vector<ExecutedRow>& rows, bool realism_columns) {
  std::string out =
      "t,x,y,theta,x_ref,y_ref,theta_ref,omega_left_cmd,omega_right_cmd,omega_left,omega_right,"
      "pos_err,heading_err";
  out += realism_columns ? ",x_est,y_est,theta_est,est_pos_err,est_heading_err,effort_left,"
                           "effort_right,torque_left,torque_right,slip_left,slip_right,"
                           "encoder_left,encoder_right\n"
                         : "\n";
  out.reserve(out.size() + rows.size() * (realism_columns ? 600 : 300));
  for (const ExecutedRow& r : rows) {
    const double values[] = {r.t_s,
                             r.pose.x,
                             r.pose.y,
                             r.pose.theta,
                             r.reference.x,
                             r.reference.y,
                             r.reference.theta,
                             r.wheels_cmd.left_radps,
                             r.wheels_cmd.right_radps,
                             r.wheels.left_radps,
                             r.wheels.right_radps,
                             r.pos_err_m,
                             r.heading_err_rad};
    for (std::size_t i = 0; i < std::size(values); ++i) {
      if (i > 0) out += ',';
      appendRoundTrip(out, values[i]);
    }
    if (realism_columns) {
      const double extra[] = {r.estimate.x,
                              r.estimate.y,
                              r.estimate.theta,
                              r.est_pos_err_m,
                              r.est_heading_err_rad,
                              r.effort.left_radps,
                              r.effort.right_radps,
                              r.torque_nm.left_radps,
                              r.torque_nm.right_radps,
                              r.slip_mps.left_radps,
                              r.slip_mps.right_radps,
                              r.encoder_rad.left_radps,
                              r.encoder_rad.right_radps};
      for (const double v : extra) {
        out += ',';
        appendRoundTrip(out, v);
      }
    }
    out += '\n';
  }
  return out;
}

void writeExecutedCsv(const std::string& path, const std::vector<ExecutedRow>& rows,
                      bool realism_columns) {
  writeFileAtomically(path, executedCsv(rows, realism_columns));
}

std::string sensorsCsv(const std::vector<PoseMeasurement>& samples, double time_step_s) {
  std::string out = "t_received,t_taken,x,y,theta\n";
  for (const PoseMeasurement& m : samples) {
    const double values[] = {static_cast<double>(m.arrival_step) * time_step_s,
                             static_cast<double>(m.taken_step) * time_step_s, m.pose.x, m.pose.y,
                             m.pose.theta};
    for (std::size_t i = 0; i < std::size(values); ++i) {
      if (i > 0) out += ',';
      appendRoundTrip(out, values[i]);
    }
    out += '\n';
  }
  return out;
}

nlohmann::json metricsToJson(const EpisodeMetrics& m) {
  nlohmann::json j;
  j["tracking"] = toString(m.tracking);
  j["max_pos_err_m"] = m.max_pos_err_m;
  j["rms_pos_err_m"] = m.rms_pos_err_m;
  j["final_pos_err_m"] = m.final_pos_err_m;
  j["max_heading_err_deg"] = m.max_heading_err_deg;
  j["rms_heading_err_deg"] = m.rms_heading_err_deg;
  j["final_heading_err_deg"] = m.final_heading_err_deg;
  j["final_x_m"] = m.final_pose.x;
  j["final_y_m"] = m.final_pose.y;
  j["final_theta_rad"] = m.final_pose.theta;
  j["goal_pos_err_m"] = m.goal_pos_err_m;
  j["goal_heading_err_deg"] = m.goal_heading_err_deg;
  j["goal_reached"] = m.goal_reached;
  j["contacts"] = m.contacts;
  // JSON has no infinity; -1 keeps the key a number for tools that read it as one.
  j["first_contact_t_s"] = m.first_contact_t_s;
  j["first_contact_body"] = m.first_contact_body;
  nlohmann::json bodies = nlohmann::json::array();
  for (const ContactEvent& e : m.contact_events) {
    if (std::find(bodies.begin(), bodies.end(), e.body) == bodies.end()) bodies.push_back(e.body);
  }
  j["contact_bodies"] = bodies;
  j["max_parked_displacement_m"] = m.max_parked_displacement_m;
  for (const ParkedRobotDisplacement& p : m.parked) {
    j["parked_displacement_m." + p.name] = p.max_m;
  }
  j["plan_duration_s"] = m.plan_duration_s;
  j["sim_time_s"] = m.sim_time_s;
  j["steps"] = m.steps;
  j["time_step_s"] = m.time_step_s;
  j["ended_at_rest"] = m.ended_at_rest;
  j["wall_time_s"] = m.wall_time_s;
  j["real_time_factor"] = m.wall_time_s > 0.0 ? m.sim_time_s / m.wall_time_s : 0.0;
  j["realism"] = m.realism;
  j["noise_seed"] = m.noise_seed;
  j["estimator"] = m.estimator;
  j["max_est_pos_err_m"] = m.max_est_pos_err_m;
  j["rms_est_pos_err_m"] = m.rms_est_pos_err_m;
  j["max_est_heading_err_deg"] = m.max_est_heading_err_deg;
  j["final_est_pos_err_m"] = m.final_est_pos_err_m;
  j["max_slip_mps"] = m.max_slip_mps;
  j["rms_slip_mps"] = m.rms_slip_mps;
  j["slip_fraction"] = m.slip_fraction;
  j["max_motor_torque_nm"] = m.max_motor_torque_nm;
  j["max_motor_effort"] = m.max_motor_effort;
  j["true_left_radius_m"] = m.true_left_radius_m;
  j["true_right_radius_m"] = m.true_right_radius_m;
  j["true_track_m"] = m.true_track_m;
  j["left_motor_gain"] = m.left_motor_gain;
  j["right_motor_gain"] = m.right_motor_gain;
  j["pose_samples_taken"] = m.pose_samples_taken;
  j["pose_samples_dropped"] = m.pose_samples_dropped;
  j["pose_samples_received"] = m.pose_samples_received;
  return j;
}

EpisodeMetrics metricsFromJson(const nlohmann::json& j) {
  auto get = [&](const char* key) -> const nlohmann::json& {
    if (!j.is_object() || !j.contains(key)) {
      throw Error(std::string("metrics: missing key '") + key + "'");
    }
    return j.at(key);
  };
  auto number = [&](const char* key) {
    const nlohmann::json& v = get(key);
    if (!v.is_number()) throw Error(std::string("metrics: key '") + key + "' is not a number");
    return v.get<double>();
  };
  EpisodeMetrics m;
  m.max_pos_err_m = number("max_pos_err_m");
  m.rms_pos_err_m = number("rms_pos_err_m");
  m.final_pos_err_m = number("final_pos_err_m");
  m.final_heading_err_deg = number("final_heading_err_deg");
  m.goal_pos_err_m = number("goal_pos_err_m");
  m.goal_heading_err_deg = number("goal_heading_err_deg");
  m.max_parked_displacement_m = number("max_parked_displacement_m");
  m.sim_time_s = number("sim_time_s");
  m.wall_time_s = number("wall_time_s");
  const double contacts = number("contacts");
  m.contacts = static_cast<int>(contacts);
  const nlohmann::json& reached = get("goal_reached");
  if (!reached.is_boolean()) throw Error("metrics: key 'goal_reached' is not a boolean");
  m.goal_reached = reached.get<bool>();
  if (j.contains("tracking") && j.at("tracking").is_string()) {
    m.tracking = trackingModeFromString(j.at("tracking").get<std::string>());
  }
  return m;
}

nlohmann::json provenanceToJson(const Provenance& p) {
  nlohmann::json j = nlohmann::json::object();
  for (const auto& [key, value] : provenanceFields(p)) j[key] = value;
  j["git_dirty"] = p.git_dirty;
  return j;
}

void writeJsonFile(const std::string& path, const nlohmann::json& json) {
  // Names and paths from input files need not be UTF-8: their bad bytes become U+FFFD.
  writeFileAtomically(path,
                      json.dump(2, ' ', false, nlohmann::json::error_handler_t::replace) + "\n");
}

nlohmann::json readJsonFile(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw Error(path + ": cannot open");
  try {
    return nlohmann::json::parse(in);
  } catch (const nlohmann::json::exception& e) {
    throw Error(path + ": not valid JSON: " + e.what());
  }
}

}  // namespace parksim
