#pragma once
// Each subcommand of the parksim executable lives in its own file and registers itself on a
// CLI11 subcommand, returning the function that runs it once the command line is parsed.
// Runners return the process exit code; bad input is reported by throwing parksim::Error,
// which main() prints as one line.

#include <functional>

#include <CLI/CLI.hpp>

namespace parksim::app {

using CommandRunner = std::function<int()>;

CommandRunner setupPlanCommand(CLI::App& sub);
CommandRunner setupRunCommand(CLI::App& sub);
CommandRunner setupRenderCommand(CLI::App& sub);
CommandRunner setupBenchCommand(CLI::App& sub);
CommandRunner setupSweepCommand(CLI::App& sub);
CommandRunner setupMergeCommand(CLI::App& sub);
CommandRunner setupReportCommand(CLI::App& sub);

}  // namespace parksim::app
