#pragma once
// A JUnit report that points at the pages: CI systems show a test case's properties, so a
// reader of a failed episode in the test report finds the page that replays it.

#include <string>

#include "parksim/results/reports/JUnitReport.h"

namespace parksim {

/// Adds the property "html_report" (the sweep page `index_path`) to every suite, and
/// "episode_report" to each case whose episode (its property episode_id) has a page under
/// `episodes_dir` (keptEpisodePage). Paths are relative to the folder of `junit_path`, where
/// CI systems resolve a report's files.
void linkJUnitToPages(JUnitReport& report, const std::string& junit_path,
                      const std::string& index_path, const std::string& episodes_dir);

}  // namespace parksim
