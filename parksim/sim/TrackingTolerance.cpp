#include "parksim/sim/TrackingTolerance.h"

#include "parksim/core/Error.h"
#include "parksim/core/NumberFormat.h"
#include "parksim/sim/EpisodeFiles.h"

namespace parksim {

namespace {

std::string exceeds(const char* name, double value, double bound) {
  return std::string(name) + " " + formatGeneral(value) + " > " + formatGeneral(bound);
}

}  // namespace

std::vector<std::string> checkTracking(const TrackingTolerance& tol, const EpisodeMetrics& m) {
  std::vector<std::string> out;
  // Written as !(value <= bound) so a NaN measurement fails instead of passing silently.
  if (!(m.max_pos_err_m <= tol.max_pos_err_m)) {
    out.push_back(exceeds("max_pos_err_m", m.max_pos_err_m, tol.max_pos_err_m));
  }
  if (!(m.goal_pos_err_m <= tol.goal_pos_err_m)) {
    out.push_back(exceeds("goal_pos_err_m", m.goal_pos_err_m, tol.goal_pos_err_m));
  }
  if (!(m.goal_heading_err_deg <= tol.goal_heading_err_deg)) {
    out.push_back(
        exceeds("goal_heading_err_deg", m.goal_heading_err_deg, tol.goal_heading_err_deg));
  }
  if (m.contacts > tol.max_contacts) {
    std::string what = exceeds("contacts", m.contacts, tol.max_contacts);
    if (!m.first_contact_body.empty()) what += " (first: " + m.first_contact_body + ")";
    out.push_back(what);
  }
  if (!(m.max_parked_displacement_m <= tol.max_parked_displacement_m)) {
    out.push_back(exceeds("max_parked_displacement_m", m.max_parked_displacement_m,
                          tol.max_parked_displacement_m));
  }
  if (tol.require_goal_reached && !m.goal_reached) {
    out.push_back("goal_reached is false");
  }
  return out;
}

std::vector<std::string> checkTrackingFile(const TrackingTolerance& tolerance,
                                           const std::string& metrics_json_path) {
  try {
    return checkTracking(tolerance, metricsFromJson(readJsonFile(metrics_json_path)));
  } catch (const Error& e) {
    return {metrics_json_path + ": " + e.what()};
  }
}

std::string joinViolations(const std::vector<std::string>& violations) {
  std::string out;
  for (const std::string& v : violations) {
    if (!out.empty()) out += "; ";
    out += v;
  }
  return out;
}

}  // namespace parksim
