#include "parksim/pipeline/Verdict.h"

#include "parksim/core/geometry/Angle.h"
#include "parksim/core/io/Error.h"
#include "parksim/core/io/NumberFormat.h"
#include "parksim/results/episode/JsonFile.h"
#include "parksim/results/episode/MetricsFile.h"

namespace parksim {

namespace {

std::string exceeds(const char* name, double value, double bound) {
  return std::string(name) + " " + formatGeneral(value) + " > " + formatGeneral(bound);
}

std::string plural(int n, const char* word) {
  return std::to_string(n) + " " + word + (n == 1 ? "" : "s");
}

}  // namespace

const char* toString(EpisodeStatus status) {
  switch (status) {
    case EpisodeStatus::kMet: return "met";
    case EpisodeStatus::kPlanFailed: return "plan_failed";
    case EpisodeStatus::kPlanInvalid: return "plan_invalid";
    case EpisodeStatus::kPlannerError: return "planner_error";
    case EpisodeStatus::kControllerError: return "controller_error";
    case EpisodeStatus::kContact: return "contact";
    case EpisodeStatus::kGoalMissed: return "goal_missed";
    case EpisodeStatus::kToleranceMissed: return "tolerance_missed";
  }
  return "?";
}

std::vector<EpisodeStatus> allEpisodeStatuses() {
  return {
      EpisodeStatus::kMet,          EpisodeStatus::kPlanFailed,      EpisodeStatus::kPlanInvalid,
      EpisodeStatus::kPlannerError, EpisodeStatus::kControllerError, EpisodeStatus::kContact,
      EpisodeStatus::kGoalMissed,   EpisodeStatus::kToleranceMissed};
}

EpisodeStatus episodeStatusFromString(const std::string& name) {
  std::string names;
  for (EpisodeStatus s : allEpisodeStatuses()) {
    if (name == toString(s)) return s;
    names += (names.empty() ? "" : ", ") + std::string(toString(s));
  }
  throw Error("unknown episode status '" + name + "' (expected one of " + names + ")");
}

Verdict planFailedVerdict(const PlanResult& plan) {
  if (plan.status == PlanStatus::kPlanInvalid) return {EpisodeStatus::kPlanInvalid, plan.message};
  return {EpisodeStatus::kPlanFailed,
          std::string("unsolved plan (") + toString(plan.status) + "): " + plan.message};
}

Verdict planInvalidVerdict(const PlanViolation& violation) {
  return {EpisodeStatus::kPlanInvalid, violation.reason};
}

Verdict userCodeVerdict(const UserCodeError& error) {
  return {error.component() == UserCodeError::Component::kPlanner ? EpisodeStatus::kPlannerError
                                                                  : EpisodeStatus::kControllerError,
          error.what()};
}

Verdict judgeEpisode(const Scenario& scenario, const TrackingTolerance& tolerance,
                     const EpisodeMetrics& m) {
  if (!m.controller_error.empty()) return {EpisodeStatus::kControllerError, m.controller_error};
  if (m.contacts > tolerance.max_contacts) {
    std::string reason = "touched " + m.first_contact_body + " at " +
                         formatFixed(m.first_contact_t_s, 3) + " s (" +
                         plural(m.contacts, "contact event");
    if (tolerance.max_contacts > 0) reason += ", at most " + std::to_string(tolerance.max_contacts);
    return {EpisodeStatus::kContact, reason + ")"};
  }
  if (!m.goal_reached) {
    return {EpisodeStatus::kGoalMissed,
            "goal not reached: ended " + formatFixed(m.goal_pos_err_m * 1e3, 3) + " mm / " +
                formatFixed(m.goal_heading_err_deg, 3) + " deg from the goal (tolerance " +
                formatFixed(scenario.goal.position_tolerance_m * 1e3, 3) + " mm / " +
                formatFixed(radToDeg(scenario.goal.heading_tolerance_rad), 3) + " deg)"};
  }
  const std::vector<std::string> violations = checkTracking(tolerance, m);
  if (!violations.empty()) {
    return {EpisodeStatus::kToleranceMissed,
            "tracking tolerance not met: " + joinViolations(violations)};
  }
  return {};
}

Verdict judgeRealisations(const std::vector<RealisationVerdict>& realisations,
                          double min_success_fraction) {
  if (realisations.empty()) throw Error("judgeRealisations: no realisations");
  std::size_t met = 0;
  const Verdict* first_failure = nullptr;
  for (const RealisationVerdict& r : realisations) {
    if (r.verdict.met()) {
      ++met;
    } else if (first_failure == nullptr) {
      first_failure = &r.verdict;
    }
  }
  // 1e-9: a fraction such as 0.95 of 20 realisations is 19 met, not 19.000000000000004.
  const double needed = min_success_fraction * static_cast<double>(realisations.size()) - 1e-9;
  if (static_cast<double>(met) >= needed || first_failure == nullptr) return {};
  return *first_failure;
}

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
