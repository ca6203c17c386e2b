#include "parksim/cli/Program.h"

#include <stdlib.h>

#include <csignal>
#include <cstdio>
#include <exception>

#include "parksim/cli/TerminalText.h"
#include "parksim/core/io/Error.h"

namespace parksim::cli {

void addOutputFlags(CLI::App& app, OutputOptions& output, const std::string& verbose_help) {
  app.add_flag("-q,--quiet", output.quiet, "print nothing but errors");
  app.add_flag("-v,--verbose", output.verbose, verbose_help);
  app.add_flag("--progress", output.progress,
               "show progress even when stderr is not a terminal (default: on a terminal)");
}

void startProgram() {
  std::signal(SIGXFSZ, SIG_IGN);
  // llvmpipe rasterizes in the drawing thread, not in threads of its own, unless the user
  // chose: a film's frame draws little over its kept lot, and handing that to rasterizer
  // threads, which compete with the PNG encoder for the cores, cost more than it saved (2
  // cores: 0.89 of the wall time of a 999-frame film, 0.94 with the 3D view; docs/rendering.md).
  // Here, before any thread, as Mesa reads it when the first renderer is made.
  ::setenv("LP_NUM_THREADS", "0", /*replace=*/0);
}

std::optional<int> parseCommandLine(CLI::App& app, int argc, char** argv,
                                    const std::string& program) {
  try {
    app.parse(argc, argv);
    return std::nullopt;
  } catch (const CLI::ParseError& e) {
    // CLI11 prints help (success); usage errors exit 2 like any bad input, printed here so the
    // option text the user gave is escaped.
    if (e.get_exit_code() == 0) return app.exit(e);
    std::fprintf(stderr, "%s: error: %s\nRun with --help for more information.\n", program.c_str(),
                 printable(e.what()).c_str());
    return kExitBadInput;
  }
}

int runReportingErrors(const std::string& program, const std::function<int()>& body) {
  try {
    return body();
  } catch (const EnvironmentError& e) {  // no OpenGL, no font: the machine, not the input
    std::fprintf(stderr, "%s: error: %s\n", program.c_str(), printable(e.what()).c_str());
    return kExitInternal;
  } catch (const Error& e) {
    std::fprintf(stderr, "%s: error: %s\n", program.c_str(), printable(e.what()).c_str());
    return kExitBadInput;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s: internal error: %s\n", program.c_str(), printable(e.what()).c_str());
    return kExitInternal;
  }
}

}  // namespace parksim::cli
