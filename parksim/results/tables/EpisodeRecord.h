#pragma once
// The one episode record: every field an episode's results hold, each defined once here with
// its key in the results table (results.jsonl, results.csv), its key in metrics.json, its unit,
// its meaning and how it is read from what the episode produced. metrics.json (and so Python's
// run().metrics), a sweep's row, the table's columns and key types, the JUnit properties and
// the column table of docs/sweeps.md (tested against recordColumnsMarkdown) all come from the
// list in EpisodeRecord.cpp: adding a metric is one entry there (and its value in
// sim/episode/EpisodeMetrics.h when the simulation measures something new).
//
//   EpisodeFacts facts;            // views of one outcome (pipeline/OutcomeFacts.h fills them)
//   nlohmann::ordered_json row;    // a sweep row: its id and parameters first (sweep/), then
//   appendRecord(facts, row);      // every field read from the outcome, in the table's order
//
// Parameters (what the episode was asked to run) are fields too, but their values are the
// table writer's (sweep/spec/EpisodeParams.h): they are what a sweep varies, not what it measured.

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "parksim/planner/base/PlanResult.h"
#include "parksim/sim/episode/EpisodeMetrics.h"

namespace parksim {

/// Where a field sits: the table's columns come group by group in this order.
enum class FieldGroup {
  kIdentity,    ///< episode_id
  kParameter,   ///< what the episode was asked to run (values from sweep/spec/EpisodeParams.h)
  kOutcome,     ///< the verdict
  kPlan,        ///< the plan's statistics
  kSimulation,  ///< what the drive measured
  kRealism,     ///< the realism layers: estimate, slip, motors, the robot as built, samples
  kTiming,      ///< wall-clock times: they differ between runs of the same episode
  kProvenance,  ///< the world file's content and the build that wrote the row
  kSeal,        ///< row_checksum (results/RowSeal.h), always last
};

enum class FieldType { kString, kBoolean, kInteger, kNumber, kList, kObject };

/// Views of what one episode produced; any may be absent (then the fields read from it are).
struct EpisodeFacts {
  /// plan.json's content (results/PlanFile.h: planSummary), or a given plan's own statistics
  /// (trajectorySummary).
  const nlohmann::json* plan_summary = nullptr;
  /// The planner's result; null for a given plan.
  const PlanResult* plan = nullptr;
  /// What the drive measured; null when nothing was driven.
  const EpisodeMetrics* metrics = nullptr;
  /// The verdict (pipeline/Verdict.h) as its text, when there is one (`judged`).
  bool judged = false;
  std::string_view status;
  bool met = false;
  std::string_view failure;
  /// World::content_hash of the world file the episode ran on; empty: unknown.
  std::string_view world_hash;
  /// Wall time of the whole episode (plan, drive, files), s; negative: not measured.
  double episode_wall_s = -1.0;
};

/// Reads a field's value from the facts; null when the facts do not have it.
using FieldReader = nlohmann::ordered_json (*)(const EpisodeFacts&);

struct EpisodeField {
  /// The key in results.jsonl and the column of results.csv; empty: not in the table.
  std::string_view key;
  /// The key in metrics.json; empty: not in metrics.json.
  std::string_view metrics_key;
  FieldGroup group;
  FieldType type;
  std::string_view unit;  ///< "m", "s", "deg", ...; empty: none
  std::string_view meaning;
  /// Null: the table's writer gives the value (parameters, provenance, the seal).
  FieldReader read = nullptr;
  /// A column of results.csv (false: results.jsonl alone holds it).
  bool csv = true;
  /// A property of the episode's JUnit test case (results/JUnitReport.h).
  bool junit = false;
  /// One key per name: the reader gives {name: value}, written as "<key>.<name>"
  /// (parked_displacement_m.robot_5); results.jsonl and metrics.json only.
  bool per_name = false;
};

/// Every field, in the table's order.
std::span<const EpisodeField> episodeFields();

/// The field whose table key is `key` (a per-name field by "<key>.<name>" too), or null.
const EpisodeField* findField(std::string_view key);

/// A parameter a sweep spec set by its path (a `set:` axis: "robot.max_wheel_speed_radps",
/// "planner.step_m", "controller.k_x"): a table key no field names and that is not a per-name
/// field's. Such keys are columns after the fixed parameters, sorted.
bool isSetKey(std::string_view key);

/// A parameter whose values are replicates, not a question asked: seed, noise_seed and sample
/// (draws of the same episode). Never an axis a report or a page summarises episodes against.
bool isReplicateKey(std::string_view key);

/// Adds every table field the facts have, read from them, in the table's order: the outcome,
/// the plan, the simulation, the realism layers, the timing and world_hash. (A row's id and
/// parameters come first, its provenance after: the table writer's.)
void appendRecord(const EpisodeFacts& facts, nlohmann::ordered_json& row);

/// Every metrics.json field the facts have, under its metrics.json key (metrics.json's
/// episode part: results/MetricsFile.h adds the document's own keys).
nlohmann::json metricsRecord(const EpisodeFacts& facts);

/// The columns of results.csv: every table field that is a column, in order, with
/// `set_columns` (sorted set keys) after the fixed parameters.
std::vector<std::string> recordColumns(const std::vector<std::string>& set_columns = {});

/// How many of recordColumns' first columns come before the set columns (episode_id and the
/// fixed parameters).
std::size_t setColumnsPosition();

/// The column table of docs/sweeps.md: one row per column (its unit and meaning), grouped,
/// then the keys results.jsonl holds beyond the columns.
std::string recordColumnsMarkdown();

}  // namespace parksim
