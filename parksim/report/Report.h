#pragma once
// `parksim report DIR`: summary tables and figures of a results table, per world x planner
// configuration x realism preset, and per parameter that varied (a parameter study: the met
// share with its interval and the error quantiles against each value, and where success turns
// to failure).

#include <cstddef>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include <nlohmann/json.hpp>

namespace parksim {

struct ReportGroup {
  std::string world;
  std::string planner;  ///< plannerLabel() of its rows
  std::string realism;
  int episodes = 0;
  int solved = 0;        ///< plans found
  int met = 0;           ///< met their tolerance
  int goal_reached = 0;  ///< ended within the world's goal tolerance
  // Per-episode samples (episodes that reached the simulation, or solved plans for the plan's).
  std::vector<double> max_err_mm;     ///< largest tracking error, mm
  std::vector<double> plan_time_ms;   ///< planning wall time, ms (every episode)
  std::vector<double> path_length_m;  ///< planned path length, m
  std::vector<double> duration_s;     ///< simulated episode duration, s
};

/// The planner configuration of a row as one label: the planner, then what differs from the
/// defaults ("rrt-star+smooth", "rrt/rotate-translate-rotate", "rrt open-loop", "rrt it=5000",
/// "rrt timing=...", "rrt goal_bias=0.1 controller=pure-pursuit controller.lookahead_s=0.2").
std::string plannerLabel(const nlohmann::ordered_json& row);

/// The group of a row in report, compare and JUnit: (world, plannerLabel, realism); a row
/// without a world reads "?", without a realism "world".
using RowGroupKey = std::tuple<std::string, std::string, std::string>;
RowGroupKey rowGroupKey(const nlohmann::ordered_json& row);
/// "<world> / <planner label> / <realism>": how every front-end names a group.
std::string rowGroupName(const RowGroupKey& key);
/// rowGroupName(rowGroupKey(row)): the JUnit suite of a record (results/JUnitReport.h).
std::string rowGroupNameOf(const nlohmann::ordered_json& row);

/// Rows grouped by (world, planner label, realism), sorted by those.
std::vector<ReportGroup> groupResults(const std::vector<nlohmann::ordered_json>& rows);

/// A Markdown table: episodes, plan solved, met tolerance, goal reached, max tracking error
/// median / p95, plan time median / p95, path length and duration medians.
std::string summaryMarkdown(const std::vector<ReportGroup>& groups);
/// The same as CSV (one row per group, numbers unrounded).
std::string summaryCsv(const std::vector<ReportGroup>& groups);

/// One value of a parameter, or a bin of values of a numeric parameter with many (a sampled
/// one), and how its episodes did.
struct ParameterLevel {
  std::string label;  ///< "6", "rrt", "[0.002, 0.0031]" for a bin
  double x = 0.0;     ///< numeric: the value, a bin's mean value; categorical: its index
  int episodes = 0;
  int met = 0;
  /// 95% Wilson score interval of met / episodes.
  double met_low = 0.0;
  double met_high = 0.0;
  std::vector<double> max_err_mm;   ///< largest tracking error of its driven episodes, mm
  std::vector<double> goal_err_mm;  ///< final error against the goal, mm
};

/// The episodes of a table against one parameter that varied in it.
struct ParameterStudy {
  std::string parameter;  ///< its column: a parameter field or a set: path
  bool numeric = false;   ///< levels in ascending value; else sorted as text
  bool binned = false;    ///< more than kMaxParameterLevels values: equal-count bins
  std::vector<ParameterLevel> levels;
};

/// Values of a numeric parameter shown one by one; more are put into this many bins.
inline constexpr std::size_t kMaxParameterLevels = 12;

/// Every parameter that took more than one value in `rows`, sorted by column: the parameter
/// fields of the record (results/EpisodeRecord.h) but the replications (seed, noise_seed,
/// sample) and world_file (world names it), and every set: column.
std::vector<ParameterStudy> parameterStudies(const std::vector<nlohmann::ordered_json>& rows);

/// Where success turns to failure along a numeric parameter: walking its values from the end
/// where every episode met its tolerance, the last such value and the next one, where some did
/// not.
struct ParameterBoundary {
  std::string parameter;
  double last_met = 0.0;
  double first_failed = 0.0;
  /// True when the values past the boundary never meet again (all the way to the far end).
  bool monotone = true;
};

/// The boundary of a one-parameter study (`study` the only parameter that varied): nothing
/// when it is not numeric, or when every value met (or none did) at both ends.
std::optional<ParameterBoundary> parameterBoundary(const std::vector<nlohmann::ordered_json>& rows,
                                                   const ParameterStudy& study);

/// Markdown: per parameter, a table of its levels (episodes, met tolerance with its interval,
/// max tracking error and goal error median / p95), then the boundary when there is one.
std::string parametersMarkdown(const std::vector<ParameterStudy>& studies,
                               const std::optional<ParameterBoundary>& boundary);
/// The same as CSV (one row per parameter and level, numbers unrounded).
std::string parametersCsv(const std::vector<ParameterStudy>& studies);

/// Writes OUT/summary.md, OUT/summary.csv and the figures success_matrix.png,
/// tracking_error.png, plan_time.png, path_length.png and duration.png (the project's
/// renderer), and for every parameter that varied (parameterStudies) a section of summary.md,
/// rows of parameters.csv and parameter_<column>.png (ParameterPlot.h), with the boundary of a
/// one-parameter study. Returns the paths written. Throws Error when a file cannot be
/// written.
std::vector<std::string> writeReport(const std::vector<nlohmann::ordered_json>& rows,
                                     const std::string& title, const std::string& out_dir);

}  // namespace parksim
