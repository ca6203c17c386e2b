// parksim: plan, simulate, render and benchmark parking manoeuvres of a two-wheel robot.

#include <cstdio>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <CLI/CLI.hpp>

#include "app/Command.h"
#include "parksim/cli/TerminalText.h"
#include "parksim/core/system/Provenance.h"

int main(int argc, char** argv) {
  using namespace parksim::app;
  parksim::cli::startProgram();
  // Named, so that usage lines say "parksim", not the path the binary was started from.
  CLI::App app{"parksim: plan, simulate, render and benchmark parking manoeuvres", "parksim"};
  app.require_subcommand(1);
  const std::string version = parksim::versionLine(parksim::buildProvenance());
  app.set_version_flag("--version", version, "print parksim's version and build, then exit");
  OutputOptions output;
  std::vector<std::pair<CLI::App*, CommandRunner>> commands;
  auto add = [&](const char* name, const char* help, CommandRunner (*setup)(CLI::App&)) {
    CLI::App* sub = app.add_subcommand(name, help);
    sub->set_version_flag("--version", version);
    parksim::cli::addOutputFlags(*sub, output, "also print the build and the settings (stderr)");
    commands.emplace_back(sub, setup(*sub));
  };
  add("plan", "plan a parking manoeuvre and write trajectory.csv and plan.json", setupPlanCommand);
  add("run", "plan (or load a plan), drive it in the Bullet simulation and measure tracking",
      setupRunCommand);
  add("render", "draw the study's figures for a world, without running an episode",
      setupRenderCommand);
  add("sweep", "run a sweep spec's episodes (plan + simulate + measure) into one results table",
      setupSweepCommand);
  add("merge", "merge sweep results (shards, machines) into one table", setupMergeCommand);
  add("report", "summary tables, figures and OMPL logs of a sweep's results", setupReportCommand);
  add("compare", "compare two sweeps' results for a regression (exit 4), with statistics",
      setupCompareCommand);
  add("verify", "check a sweep's results tables: changed rows, mixed worlds or builds",
      setupVerifyCommand);
  add("list", "the planners and controllers (built in and plugins') with their parameters",
      setupListCommand);
  add("import", "a ROS, SVG or Moving AI map as a world file to edit", setupImportCommand);

  // CLI11 says "A subcommand is required" about `parksim foo`; say what was wrong instead.
  if (argc > 1 && argv[1][0] != '-') {
    std::string names;
    bool known = false;
    for (const auto& [sub, run] : commands) {
      names += (names.empty() ? "" : ", ") + sub->get_name();
      known = known || sub->get_name() == argv[1];
    }
    if (!known) {
      // The planning benchmark is a program of its own, standing beside parksim on the library.
      const char* hint = std::string(argv[1]) == "bench"
                             ? " (the planning benchmark is the program parksim-bench)"
                             : "";
      std::fprintf(stderr, "parksim: unknown command '%s'; commands: %s%s\n",
                   parksim::cli::printable(argv[1]).c_str(), names.c_str(), hint);
      return kExitBadInput;
    }
  }
  if (const std::optional<int> ended = parksim::cli::parseCommandLine(app, argc, argv, "parksim"))
    return *ended;
  return parksim::cli::runReportingErrors("parksim", [&]() -> int {
    for (auto& [sub, run] : commands) {
      if (!sub->parsed()) continue;
      if (output.verbose) {
        std::fprintf(stderr, "%s\n", version.c_str());
        for (const CLI::Option* o : sub->get_options()) {
          if (o->count() > 0 && o->get_name() != "--help") {
            std::fprintf(stderr, "  %s = %s\n", o->get_name().c_str(),
                         o->as<std::string>().c_str());
          }
        }
      }
      // -q: the summaries go nowhere; errors still reach stderr.
      if (output.quiet && std::freopen("/dev/null", "w", stdout) == nullptr) return kExitInternal;
      return run(output);
    }
    return kExitBadInput;
  });
}
