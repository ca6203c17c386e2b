#pragma once
// A results table as a page's columns (web/sweep.js): every key any row has, in the order the
// rows first use them, so that a column added to the table (a new metric, a `set:` axis)
// shows up on the page without a change here. Objects are flattened one level
// ("plan_phase_times_s.sampling"); lists of plain values are joined with '|' as results.csv
// joins them; lists of lists (plan_cost_history) are left out and named in "omitted".
//
// Each column is packed as compactly as its values allow (ColumnCodec.h), which keeps the page
// of a 20,000-episode sweep within a few megabytes (docs/pages.md):
//   const     every row has the same value (or none): {"value": v}, stored once
//   levels    few distinct values (axes, statuses, names, booleans) or text: the distinct values
//             exactly as JSON ({"levels": [...]}, sorted when there are at most 256) and a code
//             per row
//   integer   whole numbers: ColumnCodec's integerColumn
//   number    other numbers: float32Column (7 significant digits; the table shows 4)
// and has a "kind" a page sorts and filters by: "number", "bool" or "text".

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace parksim {

/// {"rows": N, "columns": [{"name", "kind", "encoding", ...}], "omitted": [names]}.
nlohmann::json tableColumns(const std::vector<nlohmann::ordered_json>& rows);

}  // namespace parksim
