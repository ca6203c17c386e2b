#pragma once
// Each subcommand of the parksim executable lives in its own file and registers itself on a
// CLI11 subcommand, returning the function that runs it once the command line is parsed. A
// command turns its options into the library's request, makes the call and prints the
// outcome. Runners return the process exit code; bad input is reported by throwing
// parksim::Error, which main() prints as one line.

#include <functional>

#include <CLI/CLI.hpp>

#include "parksim/cli/Program.h"
#include "parksim/pipeline/Verdict.h"

namespace parksim::app {

using enum cli::ExitCode;  // kExitOk, ..., shared with parksim-bench (parksim/cli/Program.h)

/// The exit code of a single-episode command (plan, run) for its verdict: met 0, plan_failed
/// 1, contact, goal_missed and tolerance_missed 4, plan_invalid 5, planner_error and
/// controller_error 6.
int exitCodeFor(EpisodeStatus status);

using cli::OutputOptions;  // -q, -v and --progress, which every command takes

using CommandRunner = std::function<int(const OutputOptions&)>;

CommandRunner setupPlanCommand(CLI::App& sub);
CommandRunner setupRunCommand(CLI::App& sub);
CommandRunner setupRenderCommand(CLI::App& sub);
CommandRunner setupSweepCommand(CLI::App& sub);
CommandRunner setupMergeCommand(CLI::App& sub);
CommandRunner setupReportCommand(CLI::App& sub);
CommandRunner setupCompareCommand(CLI::App& sub);
CommandRunner setupVerifyCommand(CLI::App& sub);
CommandRunner setupImportCommand(CLI::App& sub);

}  // namespace parksim::app
