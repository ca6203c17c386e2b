#include "parksim/sim/EpisodeFiles.h"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "parksim/core/AtomicFile.h"
#include "parksim/core/Error.h"

namespace parksim {

std::string executedCsv(const std::vector<ExecutedRow>& rows) {
  std::string out =
      "t,x,y,theta,x_ref,y_ref,theta_ref,omega_left_cmd,omega_right_cmd,omega_left,omega_right,"
      "pos_err,heading_err\n";
  out.reserve(out.size() + rows.size() * 300);
  char line[640];
  for (const ExecutedRow& r : rows) {
    std::snprintf(line, sizeof line,
                  "%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g\n",
                  r.t_s, r.pose.x, r.pose.y, r.pose.theta, r.reference.x, r.reference.y,
                  r.reference.theta, r.wheels_cmd.left_radps, r.wheels_cmd.right_radps,
                  r.wheels.left_radps, r.wheels.right_radps, r.pos_err_m, r.heading_err_rad);
    out += line;
  }
  return out;
}

void writeExecutedCsv(const std::string& path, const std::vector<ExecutedRow>& rows) {
  writeFileAtomically(path, executedCsv(rows));
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
