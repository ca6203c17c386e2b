#pragma once
// The one verdict on an episode: did it meet its tolerance, and if not, why. Every front-end
// (`parksim run`, `parksim plan`, sweeps, Python) judges through judgeEpisode, so a check moved
// from one to another means the same. Statuses are values; their text and the exit codes of the
// single-episode commands are made at the edges (toString here, app/Command.h).
//
//   const parksim::Verdict v = parksim::judgeEpisode(scenario, tolerance, metrics);
//   EXPECT_TRUE(v.met()) << v.reason;
//
// or, on a file written by `parksim run`:
//   EXPECT_TRUE(parksim::checkTrackingFile({}, "out/metrics.json").empty());

#include <string>
#include <vector>

#include "parksim/core/io/Error.h"
#include "parksim/core/model/Scenario.h"
#include "parksim/core/model/TrackingTolerance.h"
#include "parksim/planner/base/PlanCheck.h"
#include "parksim/planner/base/PlanResult.h"
#include "parksim/sim/episode/Episode.h"

namespace parksim {

/// Outcome classes, in the order they are judged: the first that applies is the status.
enum class EpisodeStatus {
  kMet,         ///< "met": solved, driven, within every bound
  kPlanFailed,  ///< "plan_failed": no plan, so nothing was driven
  /// "plan_invalid": a plan parksim did not make (a user planner's, a plan file), or any
  /// car's plan, failed the check before driving (collision, lot bounds, speed or acceleration
  /// limits, a car's steering: planner/PlanCheck.h); not driven
  kPlanInvalid,
  /// "planner_error": the user's planner threw, returned garbage, crashed or ran out of time
  kPlannerError,
  /// "controller_error": the user's controller threw, returned NaN or out-of-range commands,
  /// crashed or ran out of time
  kControllerError,
  kContact,          ///< "contact": more contact events than TrackingTolerance::max_contacts
  kGoalMissed,       ///< "goal_missed": outside the scenario's goal tolerance at the end
  kToleranceMissed,  ///< "tolerance_missed": a TrackingTolerance bound exceeded
};

const char* toString(EpisodeStatus status);
/// Parses toString's names; throws Error otherwise.
EpisodeStatus episodeStatusFromString(const std::string& name);
/// Every status, in judging order.
std::vector<EpisodeStatus> allEpisodeStatuses();

struct Verdict {
  EpisodeStatus status = EpisodeStatus::kMet;
  /// One line saying why the episode failed, empty when met, e.g. "touched robot_5 at 17.829 s
  /// (1 contact event)".
  std::string reason;

  bool met() const { return status == EpisodeStatus::kMet; }
  friend bool operator==(const Verdict&, const Verdict&) = default;
};

/// The verdict on a plan that was not solved ("unsolved plan (iteration_limit): ..."), or that
/// failed its check (PlanStatus::kPlanInvalid: plan_invalid with the plan's message).
Verdict planFailedVerdict(const PlanResult& plan);

/// The verdict on a plan that failed its check before driving (planner/base/PlanCheck.h):
/// "plan_invalid: at t = 5.210 s (...) the footprint overlaps dropped_box".
Verdict planInvalidVerdict(const PlanViolation& violation);

/// The verdict on user code that failed (core/io/Error.h's UserCodeError): planner_error or
/// controller_error with its message.
Verdict userCodeVerdict(const UserCodeError& error);

/// The verdict on a driven episode: a controller that failed (metrics.controller_error), then
/// contacts beyond tolerance.max_contacts, then the scenario's
/// goal tolerance (metrics.goal_reached), then every other bound of `tolerance`.
Verdict judgeEpisode(const Scenario& scenario, const TrackingTolerance& tolerance,
                     const EpisodeMetrics& metrics);

/// One realisation of an episode (the same plan under one noise seed) and its verdict.
struct RealisationVerdict {
  std::uint64_t noise_seed = 0;
  Verdict verdict;
};

/// The verdict on several realisations of one plan: met when at least `min_success_fraction`
/// of them met their tolerance; otherwise the status and reason of the first that failed, so a
/// single realisation is judged exactly as judgeEpisode judges it.
Verdict judgeRealisations(const std::vector<RealisationVerdict>& realisations,
                          double min_success_fraction);

/// Descriptions of every bound of `tolerance` the metrics violate ("max_pos_err_m 0.0061 >
/// 0.005"); empty when all hold. For users' own CI asserts; judgeEpisode gives the verdict.
std::vector<std::string> checkTracking(const TrackingTolerance& tolerance,
                                       const EpisodeMetrics& metrics);

/// The same on a metrics.json file. A file that cannot be read or lacks a key is reported as a
/// violation, not thrown, so a CI script gets one list to print.
std::vector<std::string> checkTrackingFile(const TrackingTolerance& tolerance,
                                           const std::string& metrics_json_path);

/// The violations on one line, separated by "; ".
std::string joinViolations(const std::vector<std::string>& violations);

}  // namespace parksim
