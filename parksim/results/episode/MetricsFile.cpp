#include "parksim/results/episode/MetricsFile.h"

#include <algorithm>

#include "parksim/core/io/Error.h"
#include "parksim/core/system/Provenance.h"
#include "parksim/realism/Distribution.h"
#include "parksim/results/episode/JsonFile.h"
#include "parksim/results/episode/PlanFile.h"
#include "parksim/results/tables/EpisodeRecord.h"

namespace parksim {

nlohmann::json metricsToJson(const EpisodeMetrics& m) {
  EpisodeFacts facts;
  facts.metrics = &m;
  return metricsRecord(facts);
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
  if (j.contains("controller") && j.at("controller").is_string()) {
    m.controller = j.at("controller").get<std::string>();
  }

  return m;
}

namespace {

void addRealisations(nlohmann::json& j, const std::vector<MetricsDocument::Realisation>& rows) {
  std::vector<double> max_err;
  std::vector<double> goal_err;
  std::vector<double> goal_heading;
  std::vector<double> est_err;
  std::vector<double> contacts;
  std::vector<double> slip;
  int met = 0;
  int reached = 0;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const EpisodeMetrics& m = rows[i].metrics;
    const std::string p = "realisation." + std::to_string(i) + ".";
    j[p + "noise_seed"] = rows[i].noise_seed;
    j[p + "max_pos_err_m"] = m.max_pos_err_m;
    j[p + "rms_pos_err_m"] = m.rms_pos_err_m;
    j[p + "goal_pos_err_m"] = m.goal_pos_err_m;
    j[p + "goal_heading_err_deg"] = m.goal_heading_err_deg;
    j[p + "max_est_pos_err_m"] = m.max_est_pos_err_m;
    j[p + "max_slip_mps"] = m.max_slip_mps;
    j[p + "contacts"] = m.contacts;
    j[p + "goal_reached"] = m.goal_reached;
    j[p + "status"] = rows[i].status;
    j[p + "success"] = rows[i].met;
    max_err.push_back(m.max_pos_err_m);
    goal_err.push_back(m.goal_pos_err_m);
    goal_heading.push_back(m.goal_heading_err_deg);
    est_err.push_back(m.max_est_pos_err_m);
    contacts.push_back(m.contacts);
    slip.push_back(m.max_slip_mps);
    met += rows[i].met ? 1 : 0;
    reached += m.goal_reached ? 1 : 0;
  }
  const auto add = [&j](const std::string& key, const std::vector<double>& values) {
    const Distribution d = summarize(values);
    j["realisations." + key + ".median"] = d.median;
    j["realisations." + key + ".p95"] = d.p95;
    j["realisations." + key + ".max"] = d.max;
  };
  const auto n = static_cast<double>(rows.size());
  j["realisations.count"] = rows.size();
  add("max_pos_err_m", max_err);
  add("goal_pos_err_m", goal_err);
  add("goal_heading_err_deg", goal_heading);
  add("max_est_pos_err_m", est_err);
  add("contacts", contacts);
  add("max_slip_mps", slip);
  j["realisations.goal_reached_fraction"] = reached / n;
  j["realisations.success_fraction"] = met / n;
}

}  // namespace

nlohmann::json metricsDocumentJson(const MetricsDocument& doc) {
  EpisodeFacts facts;
  facts.metrics = doc.metrics ? &*doc.metrics : nullptr;
  facts.plan_summary = &doc.plan_summary;
  facts.judged = true;
  facts.status = doc.status;
  facts.met = doc.met;
  facts.failure = doc.failure;
  nlohmann::json j = metricsRecord(facts);
  // Held in a variable: a range-for over a temporary's items() would dangle.
  const nlohmann::json provenance = provenanceToJson(buildProvenance());
  for (const auto& [key, value] : provenance.items()) j["provenance." + key] = value;
  if (!doc.gl_description.empty()) j["provenance.gl"] = doc.gl_description;
  if (!doc.plugins.empty()) j["provenance.plugins"] = doc.plugins;
  j["world"] = doc.world;
  j["scenario"] = doc.scenario;
  j["tolerance.max_pos_err_m"] = doc.tolerance.max_pos_err_m;
  j["tolerance.goal_pos_err_m"] = doc.tolerance.goal_pos_err_m;
  j["tolerance.goal_heading_err_deg"] = doc.tolerance.goal_heading_err_deg;
  j["tolerance.max_contacts"] = doc.tolerance.max_contacts;
  j["tolerance.max_parked_displacement_m"] = doc.tolerance.max_parked_displacement_m;
  // Every key of plan.json, with a plan_ prefix: the record's plan fields among them, alike.
  addPlanKeys(j, doc.plan_summary);
  if (doc.realisations.size() > 1) addRealisations(j, doc.realisations);
  return j;
}

}  // namespace parksim
