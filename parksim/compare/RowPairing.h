#pragma once
// How `parksim compare` groups the rows of two tables and pairs them: by default, groups are
// `parksim report`'s (world x planner configuration x realism) and rows pair by episode id (ids
// spell every parameter: the same spec gives the same ids).
//
// Compared across columns (`--across planner`, CompareDef::across): the baseline and the
// candidate differ in those parameters by design (the user's planner against time-a-star, the
// user's controller against parksim's tracking), so
//   - a group is keyed without them: across `planner`, the planner in the group's label reads
//     "*" ("head_in / * / world", "head_in / *+smooth / world"); the other columns are not in
//     group names anyway;
//   - rows pair when every other parameter column is equal: the record's parameter fields
//     (results/EpisodeRecord.h, FieldGroup::kParameter) and the set: columns (isSetKey), but
//     world_file, which the ids leave out too (sweep/spec/EpisodeParams.h), and the columns
//     compared across.

#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "parksim/report/Report.h"

namespace parksim {

/// Why `column` cannot be compared across, or empty when it can: planner, controller, and the
/// planner's and controller's parameters (planner.NAME, controller.NAME).
std::string acrossColumnProblem(std::string_view column);

/// The grouping and pairing of rows for a list of columns compared across (empty: none).
class RowPairing {
 public:
  /// Throws Error naming the first column acrossColumnProblem refuses.
  explicit RowPairing(std::vector<std::string> across = {});

  const std::vector<std::string>& across() const { return across_; }

  /// The row's group: rowGroupKey, with the planner read as "*" across `planner`.
  RowGroupKey groupKey(const nlohmann::ordered_json& row) const;

  /// What a row pairs by: its episode_id without columns compared across; with them, every
  /// parameter column but those (and world_file), as "key=value;" sorted by key.
  std::string pairKey(const nlohmann::ordered_json& row) const;

  /// The text of a row's value of `column`: a string as it is, another value as JSON, "(none)"
  /// when the row does not have it.
  static std::string valueText(const nlohmann::ordered_json& row, const std::string& column);

 private:
  bool isAcross(std::string_view column) const;

  std::vector<std::string> across_;
};

}  // namespace parksim
