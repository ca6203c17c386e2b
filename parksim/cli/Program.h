#pragma once
// What every parksim command-line program (parksim, parksim-bench) shares around its commands:
// the exit codes, the -q/-v/--progress flags, parsing the command line and turning what a
// command throws into one line on stderr with its exit code.

#include <functional>
#include <optional>
#include <string>

#include <CLI/CLI.hpp>

namespace parksim::cli {

/// The process exit codes, the same for every program and command (README "Exit codes").
enum ExitCode : int {
  kExitOk = 0,
  kExitUnsolved = 1,         ///< the planner found no plan (plan, run)
  kExitBadInput = 2,         ///< bad input or usage; nothing was written
  kExitInternal = 3,         ///< a bug or an environment failure (out of memory, no OpenGL, ...)
  kExitToleranceNotMet = 4,  ///< run: goal or tracking tolerance missed, or a contact;
                             ///< compare: a regression
  kExitPlanInvalid = 5,      ///< plan, run: a plan parksim did not make failed its check
  kExitUserCodeFailed = 6,   ///< plan, run: the user's planner or controller failed
};

/// -q, -v and --progress, which every command takes.
struct OutputOptions {
  bool quiet = false;     ///< -q: nothing on stdout; errors only on stderr
  bool verbose = false;   ///< -v: also the build (and the settings, where shown) on stderr
  bool progress = false;  ///< --progress: draw progress even when stderr is not a terminal
};

/// Registers -q, -v (described by `verbose_help`) and --progress on `app`.
void addOutputFlags(CLI::App& app, OutputOptions& output, const std::string& verbose_help);

/// Process set-up every program does first: past a file-size limit (ulimit -f) a write then
/// fails with EFBIG and is reported like any other write error, instead of the process dying
/// with a partial file; and llvmpipe rasterizes in the drawing thread (LP_NUM_THREADS=0)
/// unless the environment already sets LP_NUM_THREADS.
void startProgram();

/// Parses the command line. Returns the exit code to end with when parsing ended the program
/// (--help or --version: 0; a usage error, printed as "<program>: error: ..." with its text
/// escaped: kExitBadInput), nothing when the command is to run.
std::optional<int> parseCommandLine(CLI::App& app, int argc, char** argv,
                                    const std::string& program);

/// Runs `body` and returns its exit code; what it throws becomes one line on stderr:
/// EnvironmentError (no OpenGL, no font: the machine) kExitInternal, Error (the input)
/// kExitBadInput, anything else "internal error" kExitInternal.
int runReportingErrors(const std::string& program, const std::function<int()>& body);

}  // namespace parksim::cli
