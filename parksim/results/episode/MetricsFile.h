#pragma once
// An episode's measurements as metrics.json's flat keys, and back.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "parksim/core/model/TrackingTolerance.h"
#include "parksim/sim/episode/Episode.h"

namespace parksim {

/// The measurements' part of metrics.json, flat: every field of the episode record
/// (EpisodeRecord.h) read from the metrics alone. Every value is a number, a boolean or a
/// string, except contact_bodies (a list of names, in the order they were first touched).
/// Parked robots get one key each, parked_displacement_m.<name>.
nlohmann::json metricsToJson(const EpisodeMetrics& metrics);

/// The metrics a TrackingTolerance checks, read back from metricsToJson's keys. Throws Error
/// naming a missing or mistyped key.
EpisodeMetrics metricsFromJson(const nlohmann::json& json);

/// Everything metrics.json holds about one episode request, as plain data.
struct MetricsDocument {
  /// The first (or only) realisation's measurements: metricsToJson's keys; none when nothing
  /// was driven (the plan failed, was invalid, or the planner failed: the verdict says which).
  std::optional<EpisodeMetrics> metrics;
  std::string world;     ///< the world file ("world")
  std::string scenario;  ///< its scenario's name ("scenario")
  /// The tolerance judged ("tolerance.<bound>").
  TrackingTolerance tolerance;
  /// The verdict: "status" (met, contact, ...), "met_tolerance", "failure" (empty when met).
  std::string status;
  bool met = false;
  std::string failure;
  /// plan.json's content; its keys are added with a plan_ prefix (addPlanKeys).
  nlohmann::json plan_summary;
  /// "provenance.gl": the renderer when the episode was filmed, else empty (no key).
  std::string gl_description;
  /// "provenance.plugins": the plugins loaded (usercode/Components.h, pluginsProvenance), else
  /// empty (no key).
  std::string plugins;

  struct Realisation {
    std::uint64_t noise_seed = 0;
    EpisodeMetrics metrics;
    std::string status;
    bool met = false;
  };
  /// With more than one: "realisation.<i>.<key>" per realisation and "realisations.<key>.median"
  /// / ".p95" / ".max" distributions, "realisations.count", the goal-reached and met fractions.
  std::vector<Realisation> realisations;
};

/// metrics.json's content for `doc`: the episode record's metrics.json fields (the
/// measurements, the verdict, the plan's statistics) with every key of plan.json as
/// plan_<key>, "provenance.<key>" of this build, the world, the tolerance and the
/// realisations.
nlohmann::json metricsDocumentJson(const MetricsDocument& doc);

}  // namespace parksim
