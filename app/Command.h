#pragma once
// Each subcommand of the parksim executable lives in its own file and registers itself on a
// CLI11 subcommand, returning the function that runs it once the command line is parsed. A
// command turns its options into the library's request, makes the call and prints the
// outcome. Runners return the process exit code; bad input is reported by throwing
// parksim::Error, which main() prints as one line.

#include <functional>

#include <CLI/CLI.hpp>

#include "parksim/pipeline/Verdict.h"

namespace parksim::app {

/// The process exit codes, the same for every command (README "Exit codes").
enum ExitCode : int {
  kExitOk = 0,
  kExitUnsolved = 1,         ///< the planner found no plan (plan, run)
  kExitBadInput = 2,         ///< bad input or usage; nothing was written
  kExitInternal = 3,         ///< a bug or an environment failure (out of memory, no OpenGL, ...)
  kExitToleranceNotMet = 4,  ///< run: goal or tracking tolerance missed, or a contact;
                             ///< compare: a regression
};

/// The exit code of a single-episode command (plan, run) for its verdict: met 0, plan_failed
/// 1, contact, goal_missed and tolerance_missed 4.
int exitCodeFor(EpisodeStatus status);

/// -q, -v and --progress, which every command takes (registered by main()).
struct OutputOptions {
  bool quiet = false;     ///< -q: nothing on stdout; errors only on stderr
  bool verbose = false;   ///< -v: also the build and the settings on stderr
  bool progress = false;  ///< --progress: draw progress even when stderr is not a terminal
};

using CommandRunner = std::function<int(const OutputOptions&)>;

CommandRunner setupPlanCommand(CLI::App& sub);
CommandRunner setupRunCommand(CLI::App& sub);
CommandRunner setupRenderCommand(CLI::App& sub);
CommandRunner setupSweepCommand(CLI::App& sub);
CommandRunner setupMergeCommand(CLI::App& sub);
CommandRunner setupReportCommand(CLI::App& sub);
CommandRunner setupCompareCommand(CLI::App& sub);
CommandRunner setupVerifyCommand(CLI::App& sub);

}  // namespace parksim::app
