#pragma once
// What is wrong with a sweep's episode folders (DIR/episodes/<id>/) after the sweep wrote them:
// files cut short (a full disk, a copy stopped half-way), emptied, deleted or overwritten. A
// page that is not whole opens blank, so it is not linked, and `parksim report` warns of each
// such folder (docs/pages.md).

#include <filesystem>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace parksim {

/// True when `page` is a file that begins as every parksim page does ("<!DOCTYPE html>") and
/// ends as one ("</html>\n"): not cut short, not another file's bytes.
bool isWholePage(const std::filesystem::path& page);

/// What is wrong with one episode's folder, as one clause ("report.html is cut short or not a
/// page; metrics.json is not JSON"), or "" when nothing is. Checked: the page is there and
/// whole (isWholePage), .json files parse, .csv files are not empty and end with a line end,
/// .npz files end with a zip archive's end record; other files are not read.
std::string episodeFolderProblem(const std::filesystem::path& folder);

/// One line per row whose folder in `episodes_dir` (an entry named by its episode_id) has a
/// problem: "<episodes_dir>/<id>: <problem>", in row order. Rows without a folder give none:
/// the table does not record which episodes kept their files, so a folder deleted whole is
/// not noticed.
std::vector<std::string> episodeFolderProblems(const std::string& episodes_dir,
                                               const std::vector<nlohmann::ordered_json>& rows);

}  // namespace parksim
