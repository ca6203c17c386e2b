#pragma once
// `parksim report DIR`: summary tables and figures of a results table, per world x planner
// configuration x realism preset.

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
/// "rrt timing=...").
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

/// Writes OUT/summary.md, OUT/summary.csv and the figures success_matrix.png,
/// tracking_error.png, plan_time.png, path_length.png and duration.png (the project's
/// renderer). Returns the paths written. Throws Error when a file cannot be written.
std::vector<std::string> writeReport(const std::vector<nlohmann::ordered_json>& rows,
                                     const std::string& title, const std::string& out_dir);

}  // namespace parksim
