#pragma once
// Each subcommand of the parksim executable lives in its own file and registers itself on a
// CLI11 subcommand, returning the function that runs it once the command line is parsed. A
// command turns its options into the library's request, makes the call and prints the
// outcome. Runners return the process exit code; bad input is reported by throwing
// parksim::Error, which main() prints as one line.

#include <functional>
#include <optional>
#include <string>

#include <CLI/CLI.hpp>

#include "parksim/cli/Program.h"
#include "parksim/core/system/UserCodeWatch.h"
#include "parksim/pipeline/Verdict.h"

namespace parksim::app {

using enum cli::ExitCode;  // kExitOk, ..., shared with parksim-bench (parksim/cli/Program.h)

/// The exit code of a single-episode command (plan, run) for its verdict: met 0, plan_failed
/// 1, contact, goal_missed and tolerance_missed 4, plan_invalid 5, planner_error and
/// controller_error 6.
int exitCodeFor(EpisodeStatus status);

/// A verdict's one line: its reason, after its status's name where the reason does not say
/// what failed ("plan_invalid: at t = ...", "controller_error: controller x threw ...").
std::string verdictLine(const Verdict& verdict);

/// Runs `body` in a watched child process when `isolate` (the request runs user code), so that
/// user code that crashes or hangs ends as a verdict: "PROGRAM: planner_error: ..." on stderr,
/// and nothing returned (the caller commits nothing and exits kExitUserCodeFailed). Otherwise
/// body(nullptr). `body` returns the exit code; it must not commit the output directory.
std::optional<int> runWatched(const char* program, bool isolate, const UserCodeLimits& limits,
                              const std::function<int(UserCodeWatch*)>& body);

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
CommandRunner setupListCommand(CLI::App& sub);
CommandRunner setupImportCommand(CLI::App& sub);

}  // namespace parksim::app
