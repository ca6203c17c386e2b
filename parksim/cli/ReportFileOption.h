#pragma once
// Options naming a report file a command writes besides its output directory (`--junit FILE`
// on run, sweep, report and compare; `--markdown FILE` on compare). The file's folder is
// checked when the command line is parsed, so a mistyped path stops the command before it has
// run anything or written a byte.

#include <string>

#include <CLI/CLI.hpp>

namespace parksim::cli {

/// Adds option `name` storing a file path in `path`: refused (usage error, exit 2) when the
/// path is empty, names a directory, or its folder does not exist.
CLI::Option* addReportFileOption(CLI::App& sub, const std::string& name, std::string& path,
                                 const std::string& help);

}  // namespace parksim::cli
