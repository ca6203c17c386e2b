#pragma once
// What differs between the two configurations a comparison sets against each other: the
// parameter and provenance columns whose values differ between the tables (a planner, a
// set: axis, the build, the world's content), and the lines of the sweeps' spec files only
// one of them has (a tolerance, a record policy: what the rows do not hold). Shown on the
// comparison's page (pages/ComparisonPage.h).

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace parksim {

struct ConfigurationDifference {
  std::string what;       ///< a column ("planner", "git_commit"), or "spec" for a spec's line
  std::string baseline;   ///< its values in the baseline (", "-joined), or the line
  std::string candidate;  ///< the same in the candidate
};

/// Values of a column listed in a difference at most; more are counted ("... (12 values)").
inline constexpr std::size_t kMaxListedValues = 5;

/// Each parameter column (but episode_id), set: column and provenance column (results/
/// EpisodeRecord.h) whose distinct values differ between the tables, in the record's order:
/// each side's distinct values, sorted, as text ("(none)" for a column a table lacks).
std::vector<ConfigurationDifference> columnDifferences(
    const std::vector<nlohmann::ordered_json>& baseline,
    const std::vector<nlohmann::ordered_json>& candidate);

/// The lines of two spec texts that only one holds, blank lines and comments aside (order
/// and repeats are not compared): "what" "spec", the line on its side and "" on the other;
/// the baseline's first, each side in its file's order.
std::vector<ConfigurationDifference> specDifferences(const std::string& baseline_text,
                                                     const std::string& candidate_text);

/// {"what", "baseline", "candidate"} per difference: what the page's data holds.
nlohmann::json differencesJson(const std::vector<ConfigurationDifference>& differences);

}  // namespace parksim
