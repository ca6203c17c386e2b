#pragma once
// A comparison (TableComparison.h) as data for its page (pages/ComparisonPage.h, `parksim
// compare --html`): the settings, every group with every metric's numbers and its one line
// (metricLine), and per group the episodes both tables hold, the worst changes first, so the
// page can link a regressed group to the episodes that show it.

#include <vector>

#include <nlohmann/json.hpp>

#include "parksim/compare/ComparisonReport.h"
#include "parksim/compare/TableComparison.h"

namespace parksim {

/// {"baseline": {path, rows}, "candidate": {...}, "settings": {confidence, max_increase,
/// min_increase_m, max_success_drop, resamples, min_samples, seed}, "tests", "regressions",
/// "regression", "only_baseline", "only_candidate", "groups": [{name, world, planner, realism,
/// paired, shared_ids, baseline_rows, candidate_rows, regression, metrics: [{name, key, q,
/// tested, note, baseline_n, candidate_n, baseline_met, candidate_met, baseline, candidate,
/// ci_low, ci_high, p, p_adjusted, regression, line}], episodes: [{id, baseline: {status, met,
/// max_pos_err_m, goal_pos_err_m}, candidate: {...}}]}]}. NaN and infinite numbers are null.
/// A group's episodes are those in both tables, ordered: met before and not after first, then
/// failed in both, then by the growth of the max tracking error, largest first. Compared
/// across columns (CompareDef::across), and only then: "across": [column, ...] at the top, each
/// group's "across": [{column, baseline, candidate}] (AcrossValues), and an episode's
/// "candidate_id" where the candidate's id is not the baseline's `id`.
nlohmann::json comparisonJson(const TableComparison& t, const CompareDef& def,
                              const ComparisonSources& sources,
                              const std::vector<nlohmann::ordered_json>& baseline,
                              const std::vector<nlohmann::ordered_json>& candidate);

}  // namespace parksim
